import { MeshStandardMaterial, ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import { LEAF_MIP_ALPHA_SCALE, applyLeafCoverage } from './leafCoverage';

function compiled(m: MeshStandardMaterial) {
  const shader = {
    vertexShader: ShaderLib.standard.vertexShader,
    fragmentShader: ShaderLib.standard.fragmentShader,
    uniforms: {} as Record<string, { value: unknown }>,
  };
  m.onBeforeCompile(shader as never, undefined as never);
  return shader;
}

describe('leaf coverage at a distance', () => {
  it('scales the map alpha by the mip level after sampling it, before the alpha test', () => {
    const m = new MeshStandardMaterial({ alphaTest: 0.5 });
    m.customProgramCacheKey = () => 'sylva-wind-leaves';
    applyLeafCoverage(m);
    const shader = compiled(m);
    const f = shader.fragmentShader;
    const scaled = f.indexOf('diffuseColor.a *= 1.0 + sylvaMip * uLeafMipAlphaScale');
    expect(scaled).toBeGreaterThan(f.indexOf('#include <map_fragment>'));
    expect(scaled).toBeLessThan(f.indexOf('#include <alphatest_fragment>'));
    // The mip level from the texel footprint of this fragment (textureSize × derivatives).
    expect(f).toContain('textureSize(map, 0)');
    expect(f).toMatch(/log2\(max\(dot\(sylvaDx, sylvaDx\), dot\(sylvaDy, sylvaDy\)\)\)/);
    expect(shader.uniforms.uLeafMipAlphaScale?.value).toBe(LEAF_MIP_ALPHA_SCALE);
    expect(m.customProgramCacheKey()).toBe('sylva-wind-leaves-sylva-leaf-coverage');
  });

  it('patches once, after the earlier patches', () => {
    const m = new MeshStandardMaterial();
    const order: string[] = [];
    m.onBeforeCompile = () => order.push('wind');
    applyLeafCoverage(m);
    const shader = compiled(m);
    m.onBeforeCompile(shader as never, undefined as never);
    expect(order).toEqual(['wind', 'wind']);
    expect(shader.fragmentShader.split('sylvaMip *').length - 1).toBe(1);
  });
});
