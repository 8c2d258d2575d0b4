/** Which renderers draw without MSAA, and at what resolution the first tree is drawn (renderQuality.ts). */
import { describe, expect, it } from 'vitest';
import { antialiasFor, firstTreePixelRatio, isSoftwareRenderer } from './renderQuality';

const SWIFTSHADER =
  'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)';

describe('render quality', () => {
  it('knows software renderers from GPUs', () => {
    expect(isSoftwareRenderer(SWIFTSHADER)).toBe(true);
    expect(isSoftwareRenderer('llvmpipe (LLVM 15.0.6, 256 bits)')).toBe(true);
    expect(isSoftwareRenderer('Microsoft Basic Render Driver')).toBe(true);
    expect(
      isSoftwareRenderer('ANGLE (NVIDIA, NVIDIA GeForce RTX 3060 Direct3D11 vs_5_0 ps_5_0)'),
    ).toBe(false);
    expect(isSoftwareRenderer('Apple M2')).toBe(false);
    expect(isSoftwareRenderer('Mali-G78')).toBe(false);
  });

  it('antialiases on GPUs and unknown renderers, not in software, unless the page says', () => {
    expect(antialiasFor('', 'Apple M2')).toBe(true);
    expect(antialiasFor('', null)).toBe(true);
    expect(antialiasFor('', SWIFTSHADER)).toBe(false);
    expect(antialiasFor('?debug=1&aa=1', SWIFTSHADER)).toBe(true);
    expect(antialiasFor('?aa=0', 'Apple M2')).toBe(false);
  });

  it('draws the first tree at half resolution in software WebGL only', () => {
    expect(firstTreePixelRatio(1, SWIFTSHADER)).toBe(0.5);
    expect(firstTreePixelRatio(2, 'llvmpipe (LLVM 15.0.6, 256 bits)')).toBe(1);
    expect(firstTreePixelRatio(2, 'Apple M2')).toBe(2);
    expect(firstTreePixelRatio(1, null)).toBe(1);
  });
});
