/**
 * The app's generation pool (`generationPool.ts`) for as long as the app is mounted:
 * [`AppPool`] makes it on first use (and no worker starts until a job needs one), and the app
 * disposes of it on unmount (under React's StrictMode, whose remount makes a fresh one on the
 * next use). Its state is on the debug hook (`window.__sylva.pool()`).
 */
import { useEffect, useState } from 'react';
import type { Params, VolumePrimitive } from 'sylva-trees/core';
import type { ExportFormat, ExportOptions, ExportResponse } from 'sylva-trees/worker';
import { installDebugHook } from '../app/debugHook';
import { createModuleWorker } from '../createWorker';
import { GenerationPool, type Exporter } from './generationPool';

/** The app's pool, made on first use and again on the first use after a dispose. */
export class AppPool implements Exporter {
  private pool: GenerationPool | null = null;

  constructor(private readonly make: () => GenerationPool) {}

  /** The pool (made now if there is none). */
  get(): GenerationPool {
    return (this.pool ??= this.make());
  }

  /** Runs an export in the pool (see `GenerationPool.export`). */
  export(
    params: Params,
    volumes: VolumePrimitive[],
    format: ExportFormat,
    options?: ExportOptions,
  ): Promise<ExportResponse> {
    return this.get().export(params, volumes, format, options);
  }

  /** Disposes of the pool made, if any (its workers stop, its jobs reject). */
  dispose(): void {
    this.pool?.dispose();
    this.pool = null;
  }
}

/** See the module docs. */
export function useGenerationPool(): AppPool {
  const [pool] = useState(() => new AppPool(() => new GenerationPool(createModuleWorker)));
  useEffect(() => {
    const uninstall = installDebugHook({ pool: () => pool.get().state() });
    return () => {
      uninstall();
      pool.dispose();
    };
  }, [pool]);
  return pool;
}
