/** "Copy embed code": the iframe and `<sylva-tree>` snippets of the current tree, with options. */
import { useEffect, useMemo, useRef, useState } from 'react';
import { elementSnippet, embedUrl, iframeSnippet, type SnippetInput } from './options';

type Base = Omit<SnippetInput, 'autorotate' | 'background' | 'width' | 'height'>;

interface Props {
  input: Base;
  onClose: () => void;
}

/** Copies text, answering whether the clipboard took it. */
async function copyText(text: string): Promise<boolean> {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    return false;
  }
}

/** Modal dialog; copies the iframe snippet as soon as it opens. */
export function EmbedDialog({ input, onClose }: Props) {
  const dialogRef = useRef<HTMLDialogElement>(null);
  const [autorotate, setAutorotate] = useState(false);
  const [background, setBackground] = useState('');
  const [copied, setCopied] = useState<string | null>(null);
  const snippets = useMemo(() => {
    const full: SnippetInput = { ...input, autorotate, background, width: 480, height: 360 };
    return { iframe: iframeSnippet(full), element: elementSnippet(full), url: embedUrl(full) };
  }, [input, autorotate, background]);
  const iframeRef = useRef(snippets.iframe);
  const onCloseRef = useRef(onClose);

  useEffect(() => {
    onCloseRef.current = onClose;
  });

  useEffect(() => {
    const dialog = dialogRef.current;
    if (!dialog) return;
    if (!dialog.open) dialog.showModal();
    const closed = () => onCloseRef.current();
    dialog.addEventListener('close', closed);
    void copyText(iframeRef.current).then((ok) =>
      setCopied(ok ? 'Embed code (iframe) copied to the clipboard.' : null),
    );
    return () => dialog.removeEventListener('close', closed);
  }, []);

  const copy = (what: 'iframe' | 'element') => {
    void copyText(snippets[what]).then((ok) =>
      setCopied(
        ok
          ? `${what === 'iframe' ? 'Iframe' : 'Element'} code copied to the clipboard.`
          : 'The clipboard is not available here: select the code and press Ctrl+C.',
      ),
    );
  };

  return (
    <dialog
      ref={dialogRef}
      className="embed-dialog"
      data-testid="embed-dialog"
      aria-labelledby="embed-title"
    >
      <h2 id="embed-title">Embed this tree</h2>
      <div className="embed-options">
        <label>
          <input
            type="checkbox"
            data-testid="embed-autorotate"
            checked={autorotate}
            onChange={(e) => setAutorotate(e.currentTarget.checked)}
          />{' '}
          Turn slowly
        </label>
        <label>
          Background{' '}
          <select
            data-testid="embed-background"
            value={background}
            onChange={(e) => setBackground(e.currentTarget.value)}
          >
            <option value="">Sky</option>
            <option value="transparent">Transparent</option>
            <option value="#ffffff">White</option>
          </select>
        </label>
      </div>
      <label className="embed-snippet">
        <span>Iframe (any page)</span>
        <textarea readOnly rows={4} value={snippets.iframe} data-testid="embed-iframe-code" />
      </label>
      <button type="button" data-testid="copy-iframe" onClick={() => copy('iframe')}>
        Copy iframe code
      </button>
      <label className="embed-snippet">
        <span>
          <code>&lt;sylva-tree&gt;</code> element (script + tag)
        </span>
        <textarea readOnly rows={4} value={snippets.element} data-testid="embed-element-code" />
      </label>
      <button type="button" data-testid="copy-element" onClick={() => copy('element')}>
        Copy element code
      </button>
      <p className="embed-copied" role="status" data-testid="embed-copied">
        {copied ?? ''}
      </p>
      <div className="embed-dialog-actions">
        <a href={snippets.url} target="_blank" rel="noopener" data-testid="embed-preview">
          Preview
        </a>
        <a href="docs.html#embedding" target="_blank" rel="noopener">
          How embedding works
        </a>
        <button type="button" data-testid="embed-close" onClick={() => dialogRef.current?.close()}>
          Close
        </button>
      </div>
    </dialog>
  );
}
