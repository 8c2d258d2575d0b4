#!/usr/bin/env bash
# `npm run package`: builds the `sylva-trees` package (packages/sylva-trees: Vite library build and
# TypeScript declarations) and packs it as sylva-trees-<version>.tgz at the repository root.
set -euo pipefail
cd "$(dirname "$0")/.."
npm run build -w packages/sylva-trees
rm -f sylva-trees-*.tgz
npm pack -w packages/sylva-trees --pack-destination . --silent >/dev/null
TGZ=$(ls sylva-trees-*.tgz)
printf '\033[1;32m[package]\033[0m %s (%s bytes)\n' "$TGZ" "$(stat -c %s "$TGZ")"
