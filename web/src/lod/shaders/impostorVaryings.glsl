// Impostor (impostor.ts): what the vertex shader passes to the fragment shader: the three
// views' uvs and atlas cells, their weights, and the quad's rotation.
varying vec2 vUv0;
varying vec2 vUv1;
varying vec2 vUv2;
varying vec2 vFrame0;
varying vec2 vFrame1;
varying vec2 vFrame2;
varying vec3 vWeights;
varying vec3 vRotX;
varying vec3 vRotY;
varying vec3 vRotZ;
