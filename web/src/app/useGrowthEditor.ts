/**
 * The interactive growth editor: the selected primitive and the gizmo mode, the GrowthOverlay in
 * the viewer, and the share URL's `vol=` key, which follows the volumes. The volumes themselves
 * live in the editor's reducer (with the params and the undo history): every edit goes through
 * `change`, and a gizmo drag of one primitive is one undo step. A drag regrows the tree on every
 * move (the scheduler is latest-wins, so only the newest shape is ever waited for).
 */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import {
  MAX_VOLUMES,
  newVolume,
  type Params,
  type VolumeGroup,
  type VolumeKind,
  type VolumePrimitive,
} from 'sylva-trees/core';
import type { EditorChange } from './useEditor';
import { decodeVolumes, encodeVolumes, VOLUMES_KEY } from 'sylva-trees/url';
import { GrowthOverlay } from '../viewer/GrowthOverlay';
import type { TreeViewer } from '../viewer/TreeViewer';
import { installDebugHook } from './debugHook';
import { withQueryEntry } from './queryEntry';

/** What the app and the Growth panel see of the editor. */
export interface GrowthEditor {
  volumes: VolumePrimitive[];
  selected: number | null;
  mode: 'translate' | 'scale';
  /** Adds a primitive and turns growth and the wireframes on (one undo step). */
  add(kind: VolumeKind, group: VolumeGroup): void;
  remove(index: number): void;
  select(index: number | null): void;
  setMode(mode: 'translate' | 'scale'): void;
  setGroup(index: number, group: VolumeGroup): void;
}

/**
 * `search` with its `vol=` entry replaced by `vol=<text>` (or removed when `text` is empty),
 * every other entry kept byte for byte (`withQueryEntry`).
 */
export function withVolumesQuery(search: string, text: string): string {
  return withQueryEntry(search, VOLUMES_KEY, text);
}

/** Writes `vol=` into the page URL (or removes it), keeping every other entry as it is. */
function writeVolumesToUrl(volumes: readonly VolumePrimitive[]): void {
  const current = window.location.search;
  const hasVolumes = current
    .replace(/^\?/, '')
    .split('&')
    .some((p) => p.split('=', 1)[0] === VOLUMES_KEY);
  const text = encodeVolumes(volumes);
  if (!text && !hasVolumes) return;
  const search = withVolumesQuery(current, text);
  if (search !== current) {
    window.history.replaceState(
      window.history.state,
      '',
      `${window.location.pathname}${search}${window.location.hash}`,
    );
  }
}

/** The primitives in the page URL's `vol=` key, with notices about anything ignored. */
export function volumesFromUrl(): { volumes: VolumePrimitive[]; messages: string[] } {
  return decodeVolumes(new URLSearchParams(window.location.search).get(VOLUMES_KEY));
}

/** The params that show a newly added primitive of `group`: growth mode, wireframes on. */
export function paramsForAdded(params: Params, group: VolumeGroup): Params {
  const next = { ...params, growth_mode: 1, show_volumes: 1 };
  return group === 'crown' ? { ...next, crown_volume: 2 } : next;
}

/**
 * See the module comment. `params` and `volumes` are the editor's; `change` records an edit.
 */
export function useGrowthEditor(
  viewerRef: RefObject<TreeViewer | null>,
  params: Params | null,
  volumes: VolumePrimitive[],
  change: (edit: EditorChange) => void,
): GrowthEditor {
  const [chosen, setSelected] = useState<number | null>(null);
  const [mode, setMode] = useState<'translate' | 'scale'>('translate');
  const overlayRef = useRef<GrowthOverlay | null>(null);
  // The latest state, for the overlay's drag callback and the stable actions.
  const latest = useRef({ params, volumes, change });
  useEffect(() => {
    latest.current = { params, volumes, change };
  });
  // An undo may remove the selected primitive.
  const selected = chosen !== null && chosen < volumes.length ? chosen : null;

  useEffect(() => {
    const viewer = viewerRef.current;
    if (!viewer) return;
    const overlay = new GrowthOverlay(viewer.overlayHost(), (index, volume) => {
      const next = latest.current.volumes.slice();
      if (index >= next.length) return;
      next[index] = volume;
      latest.current.change({ volumes: next, key: `volume:${index}` });
    });
    overlayRef.current = overlay;
    const uninstall = installDebugHook({
      growth: () => ({
        markers: overlay.markersShown,
        volumes: overlay.volumesShown,
        dragging: overlay.isDragging,
      }),
    });
    return () => {
      uninstall();
      overlay.dispose();
      if (overlayRef.current === overlay) overlayRef.current = null;
    };
  }, [viewerRef]);

  useEffect(() => {
    overlayRef.current?.update({
      growth: params?.growth_mode === 1,
      showMarkers: params?.show_markers === 1,
      showVolumes: params?.show_volumes === 1,
      params: params ?? {},
      volumes,
      selected,
      mode,
    });
  }, [params, volumes, selected, mode]);

  // The share URL follows the volumes (debounced like the params).
  useEffect(() => {
    const timer = setTimeout(() => writeVolumesToUrl(volumes), 300);
    return () => clearTimeout(timer);
  }, [volumes]);

  const add = useCallback((kind: VolumeKind, group: VolumeGroup) => {
    const { params: current, volumes: list, change: edit } = latest.current;
    if (list.length >= MAX_VOLUMES || current === null) return;
    const next = [...list, newVolume(kind, group, list.length)];
    edit({ params: paramsForAdded(current, group), volumes: next, key: null });
    setSelected(list.length);
  }, []);

  const remove = useCallback((index: number) => {
    const { volumes: list, change: edit } = latest.current;
    edit({ volumes: list.filter((_, i) => i !== index), key: null });
    setSelected(null);
  }, []);

  const setGroup = useCallback((index: number, group: VolumeGroup) => {
    const { volumes: list, change: edit } = latest.current;
    edit({ volumes: list.map((v, i) => (i === index ? { ...v, group } : v)), key: null });
  }, []);

  return { volumes, selected, mode, add, remove, select: setSelected, setMode, setGroup };
}
