/** The app's debug hook (`?debug=1`), as seen from e2e page scripts. */
interface Window {
  __sylva?: {
    panic?(): void;
    hang?(ms: number): void;
    setTimeLimit?(ms: number): void;
    geometries?(): number | null;
    trees?(): { id: number; at: number; requestedAt: number | null; preview: boolean }[];
    settleWhenIdle?(on: boolean): void;
    pauseRendering?(paused: boolean): void;
    probeFrame?(): number | null;
    leafPullCheck?(): { covered: number; differing: number } | null;
    growth?(): { markers: number; volumes: number; dragging: boolean };
    view?(from: [number, number, number], to: [number, number, number]): void;
    endGrainKind?(): number;
    edits?(): {
      tool: string | null;
      dragging: boolean;
      count: number;
      bounds: { min: number[]; max: number[] } | null;
    };
    pickBark?(x: number, y: number): [number, number, number] | null;
    project?(p: [number, number, number]): [number, number];
  };
  /** The embed page's camera hook. */
  __sylvaEmbed?: { view(from: number[], to: number[]): void };
  /** Set by the tests' init scripts. */
  __cspViolations?: string[];
  __longTasks?: { start: number; duration: number; script?: string }[];
  __xss?: unknown;
}

/** Long Animation Frames API (Chromium 123+; not yet in TypeScript's DOM types). */
interface PerformanceScriptTiming extends PerformanceEntry {
  invoker: string;
  invokerType: string;
  sourceURL: string;
  sourceFunctionName: string;
}
interface PerformanceLongAnimationFrameTiming extends PerformanceEntry {
  scripts: PerformanceScriptTiming[];
}
