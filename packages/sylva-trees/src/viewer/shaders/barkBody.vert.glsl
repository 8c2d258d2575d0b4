// Tiles around = girth / (tile_at_1m * sqrt(girth)) (BarkStyle::repeats), at least 1.
float barkGirth = 6.2831853 * max(barkRadius, 1e-4);
vBark = vec3(
  log2(max(sqrt(barkGirth) / uBarkTile, 1.0)),
  1.0 - smoothstep(0.5 * uBarkYoungRadius, 1.5 * uBarkYoungRadius, barkRadius),
  barkShade
);
