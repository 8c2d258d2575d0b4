import {
  BufferAttribute,
  BufferGeometry,
  type InterleavedBufferAttribute,
  MeshStandardMaterial,
  ShaderLib,
  UniformsUtils,
  type WebGLProgramParametersWithUniforms,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it } from 'vitest';
import {
  applyWind,
  attachWindAttributes,
  createWindDepthMaterial,
  createWindUniforms,
  patchWindShader,
  treeExtent,
  WIND_MARKER,
  WindClock,
  WindController,
} from './wind';
import { BRANCH_SWAY, LEAF_FLUTTER, MAIN_BEND, TWIG_ANGLE } from './wind.math';

type Shader = Pick<WebGLProgramParametersWithUniforms, 'vertexShader' | 'uniforms'>;

/** What three passes to `onBeforeCompile` for a MeshStandardMaterial (the vertex part). */
function standardShader(): Shader {
  return {
    vertexShader: ShaderLib.physical.vertexShader,
    uniforms: UniformsUtils.clone(ShaderLib.physical.uniforms),
  };
}

function depthShader(): Shader {
  return {
    vertexShader: ShaderLib.depth.vertexShader,
    uniforms: UniformsUtils.clone(ShaderLib.depth.uniforms),
  };
}

const UNIFORM_NAMES = [
  'uWindTime',
  'uWindDirection',
  'uWindStrength',
  'uWindGust',
  'uWindEnabled',
  'uWindTree',
];

/** Runs a material's onBeforeCompile on a copy of `shader`. */
function compile(
  material: { onBeforeCompile: MeshStandardMaterial['onBeforeCompile'] },
  shader: Shader,
): Shader {
  const copy = { ...shader, uniforms: { ...shader.uniforms } };
  material.onBeforeCompile(
    copy as WebGLProgramParametersWithUniforms,
    undefined as unknown as WebGLRenderer,
  );
  return copy;
}

describe('material patch', () => {
  it('injects the bark chunks after <common> and <begin_vertex> and binds the uniforms', () => {
    const uniforms = createWindUniforms();
    const shader = standardShader();
    patchWindShader(shader, uniforms, 'bark');
    const src = shader.vertexShader;
    expect(src).toContain(`${WIND_MARKER} bark`);
    for (const name of UNIFORM_NAMES) {
      expect(src).toContain(`uniform `);
      expect(src).toMatch(new RegExp(`uniform \\w+ ${name};`));
      // The very same objects: one update drives every material.
      expect(shader.uniforms[name]).toBe(uniforms[name]);
    }
    expect(src).toContain('attribute vec4 windPivot;');
    expect(src).toContain('attribute vec4 windParams;');
    expect(src).toContain('windSmoothTriangleWave');
    expect(src).toContain('windTwigBend(windP, windPivot, windParams, windS)');
    expect(src).toContain('uWindTree.z > 0.5 && windParams.z > 0.0');
    // Displacement happens after `transformed` exists and before projection; the lighting,
    // normal and shadow chunks are all still there.
    const begin = src.indexOf('#include <begin_vertex>');
    const body = src.indexOf('windMainBend(windQ, windS)');
    const project = src.indexOf('#include <project_vertex>');
    expect(begin).toBeGreaterThan(0);
    expect(body).toBeGreaterThan(begin);
    expect(project).toBeGreaterThan(body);
    for (const chunk of ['beginnormal_vertex', 'shadowmap_vertex', 'worldpos_vertex']) {
      expect(src).toContain(`#include <${chunk}>`);
    }
    // The shader's constants are the TS mirror's.
    for (const c of [MAIN_BEND, BRANCH_SWAY, TWIG_ANGLE]) expect(src).toContain(c.toFixed(6));
  });

  it('patches leaves with flutter and the attachment point of each instance', () => {
    const shader = standardShader();
    patchWindShader(shader, createWindUniforms(), 'leaves');
    const src = shader.vertexShader;
    expect(src).toContain(`${WIND_MARKER} leaves`);
    expect(src).toContain('instanceMatrix[3].xyz');
    expect(src).toContain('windLeafFlutter(transformed, normal, windAnchor, windS)');
    expect(src).toContain('inverse(mat3(instanceMatrix))');
    expect(src).toContain(LEAF_FLUTTER.toFixed(6));
    expect(src).not.toContain('attribute vec4 windPivot;');
  });

  it('patches only once, and refuses a shader without the chunks', () => {
    const shader = standardShader();
    const uniforms = createWindUniforms();
    patchWindShader(shader, uniforms, 'bark');
    const once = shader.vertexShader;
    patchWindShader(shader, uniforms, 'bark');
    expect(shader.vertexShader).toBe(once);
    expect(() =>
      patchWindShader({ vertexShader: 'void main() {}', uniforms: {} }, uniforms, 'bark'),
    ).toThrow(/begin_vertex/);
  });

  it('applyWind hooks onBeforeCompile with a program cache key per kind', () => {
    const uniforms = createWindUniforms();
    const bark = new MeshStandardMaterial();
    const leaves = new MeshStandardMaterial();
    applyWind(bark, uniforms, 'bark');
    applyWind(leaves, uniforms, 'leaves');
    expect(bark.customProgramCacheKey()).not.toBe(leaves.customProgramCacheKey());
    expect(bark.customProgramCacheKey()).not.toBe(
      new MeshStandardMaterial().customProgramCacheKey(),
    );
    const shader = compile(bark, standardShader());
    expect(shader.vertexShader).toContain(`${WIND_MARKER} bark`);
    expect(shader.uniforms.uWindTime).toBe(uniforms.uWindTime);
  });

  it('keeps a previous onBeforeCompile', () => {
    const material = new MeshStandardMaterial();
    let called = 0;
    material.onBeforeCompile = () => {
      called++;
    };
    applyWind(material, createWindUniforms(), 'bark');
    compile(material, standardShader());
    expect(called).toBe(1);
  });

  it('shadow depth materials move like their kind', () => {
    const uniforms = createWindUniforms();
    for (const kind of ['bark', 'leaves'] as const) {
      const depth = createWindDepthMaterial(uniforms, kind);
      const shader = compile(depth, depthShader());
      expect(shader.vertexShader).toContain(`${WIND_MARKER} ${kind}`);
      expect(shader.uniforms.uWindStrength).toBe(uniforms.uWindStrength);
      expect(depth.customProgramCacheKey()).toBe(`sylva-wind-${kind}`);
    }
  });
});

describe('per-vertex wind data', () => {
  it('wraps the core buffer as two vec4 views without copying', () => {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(9), 3));
    const wind = new Float32Array(3 * 8).map((_, i) => i);
    expect(attachWindAttributes(geometry, wind)).toBe(true);
    const pivot = geometry.getAttribute('windPivot') as InterleavedBufferAttribute;
    const params = geometry.getAttribute('windParams') as InterleavedBufferAttribute;
    expect(pivot.data.array).toBe(wind);
    expect(params.data).toBe(pivot.data);
    expect(pivot.data.stride).toBe(8);
    expect([pivot.offset, pivot.itemSize, params.offset, params.itemSize]).toEqual([0, 4, 4, 4]);
    // Vertex 1: pivot xyz + level = floats 8..11, phase/stiffness/distance/radius = 12..15.
    expect([pivot.getX(1), pivot.getY(1), pivot.getZ(1), pivot.getW(1)]).toEqual([8, 9, 10, 11]);
    expect([params.getX(1), params.getY(1), params.getZ(1), params.getW(1)]).toEqual([
      12, 13, 14, 15,
    ]);
  });

  it('ignores a missing, empty or mismatched buffer', () => {
    for (const wind of [undefined, new Float32Array(0), new Float32Array(8 * 2)]) {
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', new BufferAttribute(new Float32Array(9), 3));
      expect(attachWindAttributes(geometry, wind)).toBe(false);
      expect(geometry.hasAttribute('windPivot')).toBe(false);
    }
  });
});

describe('WindClock', () => {
  it('follows real time, capped per frame, and stands still when paused', () => {
    const clock = new WindClock();
    expect(clock.tick(1000)).toBe(0); // first tick: no previous frame
    expect(clock.tick(1016)).toBeCloseTo(0.016, 9);
    expect(clock.tick(5000)).toBeCloseTo(0.116, 9); // a hidden tab's gap counts as 0.1 s
    clock.paused = true;
    expect(clock.tick(6000)).toBeCloseTo(0.116, 9);
    clock.paused = false;
    expect(clock.tick(7000)).toBeCloseTo(0.116, 9); // resumes without a jump
    expect(clock.tick(7050)).toBeCloseTo(0.166, 9);
    clock.set(1.3);
    expect(clock.time).toBe(1.3);
    expect(clock.tick(9000)).toBe(1.3);
    clock.set(Number.NaN);
    expect(clock.time).toBe(0);
  });
});

describe('WindController', () => {
  it('maps settings to the uniforms and says when frames change over time', () => {
    let changes = 0;
    const wind = new WindController(() => changes++);
    wind.set({ enabled: true, paused: false, strength: 1.5, direction: 90, gust: 0.25 });
    const u = wind.uniforms;
    expect(u.uWindStrength.value).toBe(1.5);
    expect(u.uWindDirection.value.x).toBeCloseTo(0, 9);
    expect(u.uWindDirection.value.y).toBeCloseTo(1, 9);
    expect(u.uWindGust.value.x).toBe(0.25);
    expect(u.uWindEnabled.value).toBe(1);
    expect(wind.animating).toBe(true);
    expect(changes).toBe(1);
    wind.set({ paused: true });
    expect(wind.animating).toBe(false);
    wind.set({ paused: false, enabled: false });
    expect(u.uWindEnabled.value).toBe(0);
    expect(wind.animating).toBe(false);
    wind.set({ enabled: true, strength: 0 });
    expect(wind.animating).toBe(false);
    wind.setTime(2.5);
    expect(u.uWindTime.value).toBe(2.5);
    expect(wind.frame()).toMatchObject({ time: 2.5, strength: 0, enabled: true });
  });

  it('advances the time uniform only while animating', () => {
    const wind = new WindController();
    wind.set({ enabled: true, paused: false, strength: 1 });
    wind.tick(0);
    wind.tick(50);
    expect(wind.uniforms.uWindTime.value).toBeCloseTo(0.05, 9);
    wind.set({ paused: true });
    wind.tick(100);
    expect(wind.uniforms.uWindTime.value).toBeCloseTo(0.05, 9);
  });

  it('takes the tree size from its bounds and flags per-vertex data', () => {
    const wind = new WindController();
    wind.setTree({ min: [-3.8, 0, -5], max: [3.6, 17, 3.8] }, true);
    expect(wind.uniforms.uWindTree.value.toArray()).toEqual([17, 5, 1, 0]);
    expect(wind.hasVertexData).toBe(true);
    wind.setTree({ min: [0, 0, 0], max: [0, 0, 0] }, false);
    expect(wind.hasVertexData).toBe(false);
    expect(treeExtent({ min: [0, 0, 0], max: [0, 0, 0] })).toEqual({ height: 0.1, radius: 0.1 });
  });

  it('shares one depth material per kind and disposes them', () => {
    const wind = new WindController();
    const bark = wind.depthMaterial('bark');
    expect(wind.depthMaterial('bark')).toBe(bark);
    expect(wind.depthMaterial('leaves')).not.toBe(bark);
    let disposed = 0;
    bark.addEventListener('dispose', () => disposed++);
    wind.dispose();
    expect(disposed).toBe(1);
  });
});
