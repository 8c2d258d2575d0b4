/**
 * The LOD preview lights its impostors as the package's viewer does (the lights themselves:
 * the sylva-trees package's viewer/lighting.test.ts).
 */
import { describe, expect, it } from 'vitest';
import { impostorLights } from 'sylva-trees/viewer';
import { viewerLights } from './impostor';

describe('lighting', () => {
  it('is one definition: the LOD preview lights impostors with the viewer sun', () => {
    expect(viewerLights()).toEqual(impostorLights());
  });
});
