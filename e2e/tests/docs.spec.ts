/**
 * The docs page: every registry parameter with its default and range, embedding, the npm package
 * and the CLI.
 */
import { expect, test } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { initSync, registry_json } from '../../packages/sylva-trees/src/wasm/sylva_wasm.js';
import { watchErrors } from './helpers';

interface Spec {
  id: string;
  label: string;
  group: string;
  kind: 'float' | 'int' | 'bool' | 'enum';
  default: number;
  min: number;
  max: number;
  description: string;
  options?: string[];
}

/** The generated CLI reference, read from its file, independent of the page. */
function cliReference(): {
  commands: { name: string; synopsis: string; options: { flag: string }[]; examples: string[] }[];
} {
  const file = fileURLToPath(new URL('../../web/src/docs/cli.json', import.meta.url));
  return JSON.parse(readFileSync(file, 'utf8')) as ReturnType<typeof cliReference>;
}

/** The registry straight from the wasm core, independent of the page. */
function registry(): Spec[] {
  const wasm = fileURLToPath(
    new URL('../../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url),
  );
  initSync({ module: readFileSync(wasm) });
  return JSON.parse(registry_json()) as Spec[];
}

test('every parameter appears with label, description, default and range', async ({ page }) => {
  const errors = watchErrors(page);
  const specs = registry();
  expect(specs.length).toBeGreaterThan(50);
  await page.goto('/docs.html');
  await expect(page.locator('tr[data-param-id]')).toHaveCount(specs.length);
  const rows = await page.locator('tr[data-param-id]').evaluateAll((trs) =>
    trs.map((tr) => ({
      id: tr.getAttribute('data-param-id') ?? '',
      group: tr.closest('[data-group]')?.getAttribute('data-group') ?? '',
      text: tr.textContent ?? '',
      def: tr.querySelector('[data-testid^="doc-default-"]')?.textContent ?? '',
      range: tr.querySelector('[data-testid^="doc-range-"]')?.textContent ?? '',
    })),
  );
  const byId = new Map(rows.map((r) => [r.id, r]));
  const problems: string[] = [];
  for (const spec of specs) {
    const row = byId.get(spec.id);
    if (!row) {
      problems.push(`${spec.id}: missing`);
      continue;
    }
    if (row.group !== spec.group) problems.push(`${spec.id}: in group ${row.group}`);
    if (!row.text.includes(spec.label)) problems.push(`${spec.id}: no label`);
    if (!row.text.includes(spec.description)) problems.push(`${spec.id}: no description`);
    // Defaults are f32 values: shown without float noise.
    const def =
      spec.kind === 'enum' && spec.options
        ? (spec.options[spec.default] ?? '')
        : String(Number(spec.default.toPrecision(6)));
    if (!row.def.includes(def)) problems.push(`${spec.id}: default "${row.def}" lacks ${def}`);
    const bounds =
      spec.kind === 'enum' && spec.options
        ? spec.options
        : spec.kind === 'bool'
          ? ['0 or 1']
          : [String(spec.min), String(spec.max)];
    for (const b of bounds) {
      if (!row.range.includes(b)) problems.push(`${spec.id}: range "${row.range}" lacks ${b}`);
    }
  }
  expect(problems).toEqual([]);
  expect(errors).toEqual([]);
});

test('embedding, package and command-line sections, reachable from the contents', async ({
  page,
}) => {
  await page.goto('/docs.html#embedding');
  const embedding = page.getByTestId('docs-embedding');
  await expect(embedding).toBeInViewport();
  await expect(embedding).toContainText('<iframe src="');
  await expect(embedding).toContainText('/embed.html?v=1&seed=7');
  await expect(embedding).toContainText('<sylva-tree preset="quaking_aspen" seed="7"');
  await expect(embedding).toContainText('/sylva-tree.js"></script>');
  // The button the page names is the toolbar's (it once said "Embed").
  await expect(embedding).toContainText("The app's Copy embed code button (toolbar)");
  const attributes = page.getByTestId('docs-element-attributes');
  for (const name of ['preset', 'seed', 'params', 'autorotate', 'background']) {
    await expect(attributes.locator('code', { hasText: new RegExp(`^${name}$`) })).toHaveCount(1);
  }
  const options = page.getByTestId('docs-embed-options');
  await expect(options).toContainText('autorotate');
  await expect(options).toContainText('transparent');

  // The npm package, for a tree in the reader's own three.js scene.
  await page.getByRole('link', { name: 'In your own three.js scene' }).click();
  const library = page.getByTestId('docs-library');
  await expect(library).toBeInViewport();
  await expect(library).toContainText('npm install sylva-trees three');
  await expect(library).toContainText("await SylvaTree.create({ preset: 'quaking_aspen'");
  await expect(page.getByTestId('docs-library-api').locator('tr')).toHaveCount(10);

  // The CLI section comes from the generated reference (`sylva cli-reference --json`, checked
  // against the binary by a Rust test): every command, synopsis, option and example is shown.
  const cli = page.getByTestId('docs-cli-commands');
  const reference = cliReference();
  expect(reference.commands.map((c) => c.name)).toEqual(
    expect.arrayContaining(['generate', 'leaf', 'bench-leaf']),
  );
  await expect(cli.locator('[data-command]')).toHaveCount(reference.commands.length);
  for (const c of reference.commands) {
    const command = cli.locator(`[data-command="${c.name}"]`);
    await expect(command).toContainText(c.synopsis);
    for (const o of c.options) await expect(command).toContainText(o.flag);
    for (const e of c.examples) await expect(command).toContainText(e);
  }
  for (const usage of [
    'sylva generate [--preset NAME] [--seed N] [--age YEARS] [--set id=value]... [--volumes FILE.json]',
    '[--no-tangents]',
    'sylva envelope --shape NAME [--samples N]',
    'sylva leaf [--preset NAME]',
    'sylva bench-leaf',
  ]) {
    await expect(cli).toContainText(usage);
  }
  await page.getByRole('link', { name: 'sylva bench-leaf' }).click();
  await expect(cli.locator('[data-command="bench-leaf"]')).toBeInViewport();
  await page.getByRole('link', { name: 'Command line' }).click();
  await expect(page.getByTestId('docs-cli')).toBeInViewport();
  await expect(page.getByTestId('docs-back')).toHaveAttribute('href', 'index.html');
});
