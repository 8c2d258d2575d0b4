/** The bark look: shader patch, attributes from the wind buffer and the core's shade. */
import type { InterleavedBufferAttribute } from 'three';
import { BufferGeometry, BufferAttribute, MeshStandardMaterial, ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import {
  FALLBACK_RADIUS,
  applyBarkLook,
  attachBarkAttributes,
  createBarkLookUniforms,
  patchBarkShader,
  setBarkStyle,
} from './barkLook';
import { attachWindAttributes } from './wind';

const standard = () => ({
  vertexShader: ShaderLib.standard.vertexShader,
  fragmentShader: ShaderLib.standard.fragmentShader,
  uniforms: {},
});

describe('bark look', () => {
  it('samples every bark map through the girth-scaled blend, once', () => {
    const shader = standard();
    const u = createBarkLookUniforms();
    patchBarkShader(shader, u);
    for (const map of ['map', 'normalMap', 'roughnessMap', 'aoMap']) {
      expect(shader.fragmentShader).toMatch(new RegExp(`barkSample\\(\\s*${map}\\b`));
      // No plain fetch is left: three's tangent-space normal map once kept one, so the relief
      // was one tile around the stem while the colour had many.
      expect(shader.fragmentShader).not.toMatch(new RegExp(`texture2D\\(\\s*${map}\\s*,`));
    }
    expect(shader.fragmentShader).not.toContain('#include <map_fragment>');
    // The occlusion hides the reflections too, after the lights and before they are summed.
    const f = shader.fragmentShader;
    for (const term of ['indirectSpecular', 'directSpecular']) {
      const at = f.indexOf(`reflectedLight.${term} *= vBark.z;`);
      expect(at, term).toBeGreaterThan(f.indexOf('#include <lights_fragment_end>'));
      expect(at, term).toBeLessThan(f.indexOf('vec3 totalSpecular'));
    }
    expect(shader.vertexShader).toContain('attribute float barkRadius');
    expect(Object.keys(shader.uniforms)).toEqual(['uBarkTile', 'uBarkYoungRadius', 'uBarkYoung']);
    const once = shader.fragmentShader;
    patchBarkShader(shader, u);
    expect(shader.fragmentShader).toBe(once);
  });

  it('chains after the wind patch and keys its own program', () => {
    const m = new MeshStandardMaterial();
    let windRan = false;
    m.onBeforeCompile = () => {
      windRan = true;
    };
    m.customProgramCacheKey = () => 'sylva-wind-bark';
    applyBarkLook(m, createBarkLookUniforms());
    const shader = standard();
    m.onBeforeCompile(shader as never, undefined as never);
    expect(windRan).toBe(true);
    expect(shader.vertexShader).toContain('vBark');
    expect(m.customProgramCacheKey()).toBe('sylva-wind-bark-sylva-bark');
  });

  it('reads the radius from the wind buffer without a copy, and the shade as bytes', () => {
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(new Float32Array(6), 3));
    const wind = new Float32Array(16).map((_, i) => i);
    attachWindAttributes(g, wind);
    const shade = new Uint8Array([10, 200]);
    attachBarkAttributes(g, shade);
    const radius = g.getAttribute('barkRadius') as InterleavedBufferAttribute;
    expect(radius.data.array).toBe(wind);
    expect([radius.getX(0), radius.getX(1)]).toEqual([7, 15]);
    const s = g.getAttribute('barkShade') as BufferAttribute;
    expect(s.array).toBe(shade);
    expect(s.normalized).toBe(true);
    // No wind data, no shade: a constant radius and open sky.
    const bare = new BufferGeometry();
    bare.setAttribute('position', new BufferAttribute(new Float32Array(6), 3));
    attachBarkAttributes(bare, new Uint8Array(0));
    expect(bare.getAttribute('barkRadius').getX(1)).toBeCloseTo(FALLBACK_RADIUS);
    expect(Array.from(bare.getAttribute('barkShade').array)).toEqual([255, 255]);
  });

  it('takes a bark style', () => {
    const u = createBarkLookUniforms();
    setBarkStyle(u, {
      tile_at_1m: 0.4,
      young_radius: 0.03,
      young_rgb: [0.5, 0.25, 0.1],
      relief: 1,
    });
    expect(u.uBarkTile.value).toBe(0.4);
    expect(u.uBarkYoung.value.toArray()).toEqual([0.5, 0.25, 0.1]);
  });
});
