/**
 * The shared lights: one sun for the viewer and the impostor, leaf translucency patch. (The web
 * app's LOD preview lighting its impostors with these: web/src/lod/impostor.test.ts.)
 */
import { MeshStandardMaterial, ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import {
  LEAF_TRANSLUCENCY,
  SUN_DIRECTION,
  SUN_INTENSITY,
  applyLeafTranslucency,
  impostorLights,
} from './lighting';

describe('lighting', () => {
  it('is one definition: the impostor lights with the viewer sun', () => {
    const l = impostorLights();
    expect(l.sunDir.toArray()).toEqual(SUN_DIRECTION.toArray());
    expect(l.sunColor.r).toBeGreaterThan(SUN_INTENSITY * 0.9);
    expect(l.sky.b).toBeGreaterThan(l.ground.b);
  });

  it('adds translucency to the leaf shader after earlier patches', () => {
    const m = new MeshStandardMaterial();
    m.customProgramCacheKey = () => 'sylva-wind-leaves';
    applyLeafTranslucency(m);
    const shader = {
      vertexShader: ShaderLib.standard.vertexShader,
      fragmentShader: ShaderLib.standard.fragmentShader,
      uniforms: {} as Record<string, { value: unknown }>,
    };
    m.onBeforeCompile(shader as never, undefined as never);
    expect(shader.fragmentShader).toContain('leafBack');
    expect(shader.fragmentShader.indexOf('leafBack')).toBeLessThan(
      shader.fragmentShader.indexOf('#include <aomap_fragment>'),
    );
    expect(shader.uniforms.uLeafTranslucency?.value).toBe(LEAF_TRANSLUCENCY);
    expect(m.customProgramCacheKey()).toBe('sylva-wind-leaves-sylva-leaf-light');
  });
});
