/** Error banner: generator errors (naming the parameter) and share-link notices, as plain text. */
import { describeError } from '../core/describeError';
import type { ParamSpec, SylvaError } from 'sylva-trees/core';

interface Props {
  error: SylvaError | null;
  notices: readonly string[];
  registry: readonly ParamSpec[];
  onDismiss: () => void;
}

/** How a panic is introduced: the app restarts the worker and keeps the last tree. */
const CRASHED = 'The generator crashed and was restarted (last good tree kept)';

/** Renders nothing when there is nothing to say; text is only ever rendered as text. */
export function ErrorBanner({ error, notices, registry, onDismiss }: Props) {
  if (!error && notices.length === 0) return null;
  return (
    <div className="error-banner" role="alert" data-testid="error-banner">
      <div className="error-lines">
        {error ? (
          <p data-testid="error-generator" data-kind={error.kind}>
            {describeError(error, registry, CRASHED)}
          </p>
        ) : null}
        {notices.map((notice, i) => (
          <p key={i} data-testid="error-notice">
            {notice}
          </p>
        ))}
      </div>
      <button type="button" className="dismiss" aria-label="Dismiss" onClick={onDismiss}>
        ×
      </button>
    </div>
  );
}
