/** Frame read-back for the debug hook: a hash of the drawing buffer's pixels. */

/** FNV-1a (32 bit) over 32-bit words of `bytes` (length a multiple of 4), as 8 hex digits. */
export function hashBytes(bytes: Uint8Array): string {
  const words = new Uint32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength >> 2);
  let h = 0x811c9dc5;
  for (let i = 0; i < words.length; i++) {
    h = Math.imul(h ^ (words[i] ?? 0), 0x01000193);
  }
  return (h >>> 0).toString(16).padStart(8, '0');
}

/**
 * Reads the whole drawing buffer (call right after rendering, in the same task, before the
 * browser presents it) and hashes it.
 */
export function hashPixels(gl: WebGLRenderingContext | WebGL2RenderingContext): string {
  const width = gl.drawingBufferWidth;
  const height = gl.drawingBufferHeight;
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return `${width}x${height}:${hashBytes(pixels)}`;
}
