/** Pulled leaves: the shader rewrite on three's own shaders, and the textures' layouts. */
import { MeshDepthMaterial, MeshStandardMaterial, ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import {
  applyLeafPull,
  LEAF_PULL_MARKER,
  LEAVES_PER_ROW,
  LeafPullData,
  pullLeafVertexShader,
  ROW_STEP,
} from './leafPull';
import { applyWind, createWindUniforms } from './wind';

/** Runs a material's `onBeforeCompile` on three's source for it. */
function compiled(material: MeshStandardMaterial | MeshDepthMaterial, lib: 'standard' | 'depth') {
  const shader = {
    uniforms: {} as Record<string, { value: unknown }>,
    vertexShader: ShaderLib[lib].vertexShader,
    fragmentShader: ShaderLib[lib].fragmentShader,
  };
  material.onBeforeCompile(shader as never, null as never);
  return shader;
}

describe('pulled leaf shaders', () => {
  it('turns on the instancing chunks over locals read from the textures', () => {
    const src = pullLeafVertexShader(ShaderLib.standard.vertexShader);
    // Before every chunk: the chunks' `#ifdef USE_INSTANCING` code sees the local matrix.
    expect(src.indexOf('#define USE_INSTANCING')).toBeLessThan(src.indexOf('#include <common>'));
    const main = src.slice(src.indexOf('void main() {'));
    for (const local of ['vec3 position', 'vec3 normal', 'vec2 uv', 'mat4 instanceMatrix']) {
      expect(main.indexOf(local), local).toBeGreaterThan(0);
      expect(main.indexOf(local), local).toBeLessThan(main.indexOf('#include <begin_vertex>'));
    }
    expect(main).toContain('vec3 color = texelFetch(sylvaLeafTints');
    expect(main).toContain('gl_VertexID / sylvaLeafIndices');
    expect(pullLeafVertexShader(src)).toBe(src);
    expect(() => pullLeafVertexShader('void f() {}')).toThrow(/main/);
  });

  it('runs after the wind, whose leaf code reads the pulled matrix, and keys the program', () => {
    const data = new LeafPullData();
    const material = new MeshStandardMaterial({ vertexColors: true });
    applyWind(material, createWindUniforms(), 'leaves');
    const windKey = material.customProgramCacheKey();
    applyLeafPull(material, data.uniforms);
    expect(material.customProgramCacheKey()).toBe(`${windKey}-sylva-leaf-pull`);
    const shader = compiled(material, 'standard');
    expect(shader.vertexShader.split(LEAF_PULL_MARKER)).toHaveLength(2);
    expect(shader.vertexShader).toContain('instanceMatrix[3].xyz');
    expect(shader.uniforms.sylvaLeafIndices).toBe(data.uniforms.sylvaLeafIndices);
    // The shadow depth material is pulled the same way.
    const depth = new MeshDepthMaterial();
    applyLeafPull(depth, data.uniforms);
    expect(compiled(depth, 'depth').vertexShader).toContain(LEAF_PULL_MARKER);
  });
});

describe('pulled leaf textures', () => {
  it('hold the transferred matrices and tints as they are, LEAVES_PER_ROW leaves a row', () => {
    const data = new LeafPullData();
    const count = LEAVES_PER_ROW + 3;
    const matrices = Float32Array.from({ length: count * 16 }, (_, i) => i);
    const tints = Float32Array.from({ length: count * 3 }, (_, i) => -i);
    data.setMesh({
      positions: new Float32Array(12),
      normals: new Float32Array(12),
      uvs: new Float32Array(8),
      indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
    });
    data.setInstances(matrices, tints);
    const m = data.uniforms.sylvaLeafMatrices.value!;
    const t = data.uniforms.sylvaLeafTints.value!;
    expect([m.image.width, m.image.height]).toEqual([4 * LEAVES_PER_ROW, ROW_STEP]);
    expect([t.image.width, t.image.height]).toEqual([LEAVES_PER_ROW, ROW_STEP]);
    expect(m.internalFormat).toBe('RGBA32F');
    expect(t.internalFormat).toBe('RGB32F');
    // Leaf LEAVES_PER_ROW + 1 starts the second row's second group of 4 texels.
    const leaf = LEAVES_PER_ROW + 1;
    const texel = (4 * LEAVES_PER_ROW + 4) * 4;
    expect((m.image.data as Float32Array)[texel]).toBe(leaf * 16);
    expect((t.image.data as Float32Array)[(LEAVES_PER_ROW + 1) * 3 + 2]).toBe(-(leaf * 3 + 2));
    expect(data.count).toBe(count);
    expect(data.vertexCount).toBe(count * 6);
    expect(data.geometry.drawRange.count).toBe(count * 6);
    expect(() => data.setInstances(new Float32Array(16), new Float32Array(6))).toThrow(
      /1 matrices for 2 leaves/,
    );
  });
});
