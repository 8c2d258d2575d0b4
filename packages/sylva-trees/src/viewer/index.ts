/**
 * `sylva-trees/viewer`: the three.js pieces `SylvaTree` is made of, for apps that compose their
 * own scenes (the studio's viewer, LOD preview and forest). The tree object (bark, leaves, wind),
 * the shared sun and sky lights and soft shadows, leaf textures and alpha coverage, instancing,
 * the bark look, leaf pulling, the growth-volume envelope, and the wind settings a user picks.
 */
export { TreeObject } from './TreeObject';
export { SceneLights, impostorLights, type ImpostorLights } from './lighting';
export { applySoftShadows } from './softShadows';
export { buildEnvelopeGeometry, MATERIAL_INDEX } from './geometry';
export { createCutFaceMaterial, EndGrainTextures } from './cutFaceMaterial';
export { leafTexture, srgbTexture } from './leafTexture';
export { applyLeafCoverage } from './leafCoverage';
export { LEAF_INSTANCED_MATERIAL_KEY, LEAF_MATRICES_KEY, LEAF_TRANSLUCENCY } from './Foliage';
export { wrapInstances } from './instances';
export { OrganSets, ORGAN_MESH_PREFIX, organMaterial, organGeometry } from './organs';
export { attachBarkAttributes } from './barkLook';
export { applyLeafPull, LeafPullData } from './leafPull';
export type { WindController } from './wind';
export { loadWind, sanitizeWind, saveWind, WIND_LIMITS, type WindSettings } from './windSettings';
