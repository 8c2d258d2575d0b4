// Bark look (barkLook.ts): how many tiles go around the stem, how young and how shaded it is.
attribute float barkRadius;
attribute float barkShade;
uniform float uBarkTile;
uniform float uBarkYoungRadius;
// x = log2(tiles around the stem), y = youth 0..1, z = occlusion 0..1.
varying vec3 vBark;
