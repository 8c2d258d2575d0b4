// Impostor (impostor.ts): what the vertex shader passes to the fragment shader: the three
// views' atlas cells and weights, the eye and the quad point in the tree's frame (in units of the
// bounding radius, centred on its centre: each fragment casts its own ray), and the quad's rotation.
varying vec2 vFrame0;
varying vec2 vFrame1;
varying vec2 vFrame2;
varying vec3 vWeights;
varying vec3 vEye;
varying vec3 vLocal;
varying vec3 vRotX;
varying vec3 vRotY;
varying vec3 vRotZ;
