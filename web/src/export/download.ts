/** Browser downloads through blob: URLs (allowed by the CSP; no data: navigation). */

/** Saves `blob` as a file named `name`. */
export function downloadBlob(blob: Blob, name: string): void {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  link.rel = 'noopener';
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  // The download has started reading the blob by then.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}

/** Renders the viewer now and encodes its canvas as PNG (same task: no preserveDrawingBuffer). */
export function canvasPng(canvas: HTMLCanvasElement, render: () => void): Promise<Blob> {
  return new Promise((resolve, reject) => {
    render();
    canvas.toBlob((blob) => {
      if (blob) resolve(blob);
      else reject(new Error('the canvas could not be encoded as PNG'));
    }, 'image/png');
  });
}

/** Reads a user-chosen file as text, refusing anything larger than `maxBytes`. */
export async function readTextFile(file: File, maxBytes: number): Promise<string> {
  if (file.size > maxBytes) {
    throw new Error(`"${file.name}" is too large for a Sylva preset (${file.size} bytes).`);
  }
  return file.text();
}
