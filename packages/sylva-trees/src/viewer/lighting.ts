/**
 * The one definition of Sylva's light, shared by the viewer (`TreeViewer`), the forest
 * (`ForestScene`) and the impostor baker (`lod/impostor.ts`): a procedural sky (gradient plus sun
 * glow, no downloaded HDR) prefiltered once per page into a PMREM environment map
 * (`skyEnvironment.ts`, on the CPU: three's GPU bake took seconds of software WebGL), the
 * image-based light, a sun with soft shadows fitted to the tree, and leaf
 * translucency when the sun is behind a leaf (leaves oriented to the light, the "top oriented
 * leaves" of the WebGL notes after Bloomenthal's *Modeling the Mighty Maple* (docs/user-guide.md,
 * Foliage), face the sky; seen from below against the sun they glow). The crown-depth term
 * that darkens inner leaves and bark comes from the core (`crown_shade.rs`, `mesh::shade`).
 */
import type { Scene } from 'three';
import {
  Color,
  DirectionalLight,
  Vector3,
  type Material,
  type Sphere,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { chainFragmentPatch } from './fragmentPatch';
import leafTranslucency from './shaders/leafTranslucency.frag.glsl?raw';
import { prefilterSky, skyEnvironmentTexture, type Sky } from './skyEnvironment';

/** Direction toward the sun (world, y up). */
export const SUN_DIRECTION = new Vector3(0.5, 1, 0.35).normalize();
/** Sun colour and intensity. */
export const SUN_COLOR = '#fff3dc';
export const SUN_INTENSITY = 2.6;
/** Sky colours (linear): zenith, horizon and ground bounce. */
export const SKY_ZENITH = new Color(0.42, 0.53, 0.7);
export const SKY_HORIZON = new Color(0.8, 0.8, 0.78);
export const SKY_GROUND = new Color(0.22, 0.18, 0.13);
/** Strength of the sky's image-based light. */
export const ENVIRONMENT_INTENSITY = 0.75;
/** How much sunlight a leaf lets through (0..1). */
export const LEAF_TRANSLUCENCY = 0.45;
/** Shadow map edge (texels) and blur radius: soft, affordable on software WebGL. */
export const SHADOW_MAP_SIZE = 1024;
export const SHADOW_RADIUS = 6;

/** The procedural sky of every scene (skyEnvironment.ts). */
export const SKY: Sky = {
  zenith: SKY_ZENITH,
  horizon: SKY_HORIZON,
  ground: SKY_GROUND,
  sunGlow: new Color(SUN_COLOR).multiplyScalar(0.35),
  sunDirection: SUN_DIRECTION,
};

/** The prefiltered sky, computed once per page (the same sky for every scene). */
let prefiltered: Float32Array[][] | null = null;

/** The sky's prefiltered (PMREM) environment map, a new texture (computed once per page). */
export function skyEnvironment(): Texture {
  prefiltered ??= prefilterSky(SKY);
  return skyEnvironmentTexture(prefiltered);
}

/** The sun and sky of one scene. */
export class SceneLights {
  readonly sun = new DirectionalLight(SUN_COLOR, SUN_INTENSITY);
  private readonly environment: Texture;

  /** `renderer`: the renderer that draws `scene` (the sky's map is uploaded to it now). */
  constructor(
    private readonly scene: Scene,
    renderer: WebGLRenderer,
    options: { shadows: boolean },
  ) {
    this.environment = skyEnvironment();
    renderer.initTexture(this.environment);
    scene.environment = this.environment;
    scene.environmentIntensity = ENVIRONMENT_INTENSITY;
    this.sun.position.copy(SUN_DIRECTION);
    if (options.shadows) {
      this.sun.castShadow = true;
      this.sun.shadow.mapSize.set(SHADOW_MAP_SIZE, SHADOW_MAP_SIZE);
      this.sun.shadow.radius = SHADOW_RADIUS;
      this.sun.shadow.bias = -0.0005;
      this.sun.shadow.normalBias = 0.02;
    }
    scene.add(this.sun, this.sun.target);
  }

  /** Aims the sun at a tree and fits its shadow camera (and so the shadows' softness) to it. */
  fit(sphere: Sphere): void {
    const r = Math.max(sphere.radius, 0.01);
    this.sun.target.position.set(sphere.center.x, 0, sphere.center.z);
    this.sun.position.copy(sphere.center).addScaledVector(SUN_DIRECTION, r * 3);
    const cam = this.sun.shadow.camera;
    cam.left = -r * 1.3;
    cam.right = r * 1.3;
    cam.top = r * 1.3;
    cam.bottom = -r * 1.3;
    cam.near = r * 0.05;
    cam.far = r * 6;
    cam.updateProjectionMatrix();
  }

  dispose(): void {
    this.environment.dispose();
    this.scene.environment = null;
  }
}

/** The impostor's light model (linear colours × intensity, direction toward the sun). */
export interface ImpostorLights {
  sunDir: Vector3;
  sunColor: Color;
  sky: Color;
  ground: Color;
}

/** These lights for the impostor's hemisphere + sun model. */
export function impostorLights(): ImpostorLights {
  return {
    sunDir: SUN_DIRECTION.clone(),
    sunColor: new Color(SUN_COLOR).multiplyScalar(SUN_INTENSITY),
    sky: SKY_ZENITH.clone()
      .lerp(SKY_HORIZON, 0.5)
      .multiplyScalar(ENVIRONMENT_INTENSITY * Math.PI),
    ground: SKY_GROUND.clone().multiplyScalar(ENVIRONMENT_INTENSITY * Math.PI),
  };
}

/** Adds leaf translucency to a (double-sided) MeshStandardMaterial, after any earlier patch. */
export function applyLeafTranslucency(material: Material): void {
  chainFragmentPatch(material, {
    key: 'sylva-leaf-light',
    at: '#include <aomap_fragment>',
    where: 'before',
    code: leafTranslucency,
    uniforms: { uLeafTranslucency: LEAF_TRANSLUCENCY },
  });
}
