/** Soft shadows: three's noise-rotated PCF taps replaced by a fixed 16-tap disk. */
import { MeshLambertMaterial, ShaderChunk, ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import { applySoftShadows, SOFT_SHADOW_TAPS, softShadowChunk, vogelDisk } from './softShadows';

describe('soft shadows', () => {
  it('replaces only the directional filter, keeping the rest of the chunk', () => {
    const three = ShaderChunk.shadowmap_pars_fragment;
    const ours = softShadowChunk();
    // three rotates its taps per pixel in two places (directional and point lights); one stays.
    const noise = 'interleavedGradientNoise( gl_FragCoord.xy )';
    expect(three.split(noise).length - ours.split(noise).length).toBe(1);
    expect(ours).toContain(`const vec2 sylvaTaps[ ${SOFT_SHADOW_TAPS} ]`);
    expect(ours).toContain(`for ( int i = 0; i < ${SOFT_SHADOW_TAPS}; i ++ )`);
    expect(ours).toContain('float getShadow( sampler2DShadow shadowMap');
    expect(ours.length).toBeGreaterThan(three.length * 0.9);
  });

  it('spreads its taps over the unit disk, no two at one place', () => {
    const disk = vogelDisk(SOFT_SHADOW_TAPS);
    const radii = disk.map(([x, y]) => Math.hypot(x, y));
    expect(Math.max(...radii)).toBeLessThanOrEqual(1);
    expect(Math.max(...radii)).toBeGreaterThan(0.95);
    let nearest = Infinity;
    for (let i = 0; i < disk.length; i++) {
      for (let j = 0; j < i; j++) {
        nearest = Math.min(
          nearest,
          Math.hypot(disk[i]![0] - disk[j]![0], disk[i]![1] - disk[j]![1]),
        );
      }
    }
    // About the spacing of an even packing of 16 points in the disk.
    expect(nearest).toBeGreaterThan(0.25);
    // Centred: the blur does not shift the shadow.
    const mean = disk.reduce(
      (s, [x, y]) => [s[0] + x / disk.length, s[1] + y / disk.length],
      [0, 0],
    );
    expect(Math.hypot(mean[0], mean[1])).toBeLessThan(0.05);
  });

  it('patches a material once, after its earlier patches, and keys its program', () => {
    const material = new MeshLambertMaterial();
    applySoftShadows(material);
    const shader = {
      uniforms: {},
      vertexShader: ShaderLib.lambert.vertexShader,
      fragmentShader: ShaderLib.lambert.fragmentShader,
    };
    material.onBeforeCompile(shader as never, null as never);
    expect(shader.fragmentShader).not.toContain('#include <shadowmap_pars_fragment>');
    expect(shader.fragmentShader).toContain('sylva-soft-shadows');
    expect(material.customProgramCacheKey()).toMatch(/-sylva-soft-shadows$/);
  });
});
