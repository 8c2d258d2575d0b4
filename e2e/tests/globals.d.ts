/** The app's debug hook (`?debug=1`), as seen from e2e page scripts. */
interface Window {
  __sylva?: {
    panic?(): void;
    hang?(ms: number): void;
    setTimeLimit?(ms: number): void;
    geometries?(): number | null;
    growth?(): { markers: number; volumes: number; dragging: boolean };
  };
  /** Set by the tests' init scripts. */
  __cspViolations?: string[];
  __longTasks?: { start: number; duration: number }[];
  __xss?: unknown;
}
