/**
 * Whether the viewer's canvas is multisampled. On a GPU, 4× MSAA costs little; in software
 * WebGL (SwiftShader, Mesa's llvmpipe, a VM or a machine without a GPU driver) every sample is
 * shaded on the CPU, and a frame of the default tree took 2.4–3.3 s with it against 1.1–1.3 s
 * without (headless Chromium, 2 cores). So software renderers draw without MSAA unless the page
 * asks for it (`aa=1`, as the gallery does); `aa=0` turns it off anywhere.
 */

/** Whether the WebGL renderer called `name` rasterises on the CPU. */
export function isSoftwareRenderer(name: string): boolean {
  return /swiftshader|llvmpipe|softpipe|software|basic render driver/i.test(name);
}

/** Whether to ask for an antialiased context, given the page's query string and renderer name. */
export function antialiasFor(search: string, rendererName: string | null): boolean {
  const aa = new URLSearchParams(search).get('aa');
  if (aa === '1') return true;
  if (aa === '0') return false;
  return rendererName === null || !isSoftwareRenderer(rendererName);
}

let probed: string | null | undefined;

/**
 * The name of the WebGL2 renderer this page gets (null if unknown), from a throwaway context
 * that is released at once; probed once per page.
 */
export function webglRendererName(): string | null {
  if (probed !== undefined) return probed;
  probed = null;
  try {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (gl) {
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      const name: unknown = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
      probed = typeof name === 'string' ? name : null;
      gl.getExtension('WEBGL_lose_context')?.loseContext();
    }
  } catch {
    probed = null;
  }
  return probed;
}

/** Share of the pixel ratio the page's first tree frame is drawn at in software WebGL. */
export const FIRST_TREE_RESOLUTION = 0.5;

/**
 * The pixel ratio to draw the page's first tree frame at. In software WebGL that frame is the
 * slowest of the session (its pipelines are built, its textures uploaded and every pixel shaded
 * on the CPU: about 0.8 s for the default tree at 1000×700), so it is drawn at half the
 * resolution (a quarter of the pixels), which shows the tree about 0.2 s sooner; the next frame,
 * the one that adds the shadows, draws it sharp (TreeViewer.draw). On a GPU, or with a renderer
 * of unknown name, the first frame is drawn like every other.
 */
export function firstTreePixelRatio(pixelRatio: number, rendererName: string | null): number {
  const software = rendererName !== null && isSoftwareRenderer(rendererName);
  return software ? pixelRatio * FIRST_TREE_RESOLUTION : pixelRatio;
}
