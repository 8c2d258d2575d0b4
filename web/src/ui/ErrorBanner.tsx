/** Error banner: generator errors (naming the parameter) and share-link notices, as plain text. */
import type { ParamSpec, SylvaError } from '../core/types';

interface Props {
  error: SylvaError | null;
  notices: readonly string[];
  registry: readonly ParamSpec[];
  onDismiss: () => void;
}

/** Human-readable text for a generator error. */
export function describeError(error: SylvaError, registry: readonly ParamSpec[]): string {
  if (error.kind === 'panic') {
    return `The generator crashed and was restarted (last good tree kept): ${error.message}`;
  }
  if (error.param) {
    const spec = registry.find((s) => s.id === error.param);
    const name = spec ? `${spec.label} (${error.param})` : error.param;
    return `Invalid parameter ${name}: ${error.message}`;
  }
  if (error.kind === 'budget') return `Tree too large: ${error.message}`;
  return error.message;
}

/** Renders nothing when there is nothing to say; text is only ever rendered as text. */
export function ErrorBanner({ error, notices, registry, onDismiss }: Props) {
  if (!error && notices.length === 0) return null;
  return (
    <div className="error-banner" role="alert" data-testid="error-banner">
      <div className="error-lines">
        {error ? (
          <p data-testid="error-generator" data-kind={error.kind}>
            {describeError(error, registry)}
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
