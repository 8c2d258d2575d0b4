/**
 * Chaining a fragment-shader patch onto a three.js material after the patches it already has
 * (wind, translucency, coverage): the patch's uniforms are declared after `#include <common>`,
 * its code goes in before or after one `#include` of the standard shader, it is applied once,
 * and the program cache key grows by the patch's key so patched and plain materials never
 * share a program.
 */
import type { Material } from 'three';

/** One fragment patch. */
export interface FragmentPatch {
  /** Appended to the program cache key (and marks the shader as patched). */
  key: string;
  /** The `#include` the code goes next to, e.g. `#include <map_fragment>`. */
  at: string;
  /** Before or after `at`. */
  where: 'before' | 'after';
  /** GLSL inserted at `at`. */
  code: string;
  /** Float uniforms the code reads, with their values. */
  uniforms: Record<string, number>;
}

/** Adds `patch` to `material` after any earlier `onBeforeCompile`. */
export function chainFragmentPatch(material: Material, patch: FragmentPatch): void {
  const previous = material.onBeforeCompile.bind(material);
  const previousKey = material.customProgramCacheKey.bind(material);
  const marker = `// ${patch.key}`;
  material.onBeforeCompile = (shader, renderer) => {
    previous(shader, renderer);
    if (shader.fragmentShader.includes(marker)) return;
    if (!shader.fragmentShader.includes(patch.at)) throw new Error(`${patch.key}: no ${patch.at}`);
    const declarations = Object.keys(patch.uniforms).map((u) => `uniform float ${u};`);
    const placed =
      patch.where === 'before' ? `${patch.code}\n${patch.at}` : `${patch.at}\n${patch.code}`;
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <common>', ['#include <common>', marker, ...declarations].join('\n'))
      .replace(patch.at, placed);
    for (const [name, value] of Object.entries(patch.uniforms)) shader.uniforms[name] = { value };
  };
  material.customProgramCacheKey = () => `${previousKey()}-${patch.key}`;
  material.needsUpdate = true;
}
