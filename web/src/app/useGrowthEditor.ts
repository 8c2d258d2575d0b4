/**
 * The interactive growth editor's state: the user's volume primitives (loaded from the share
 * URL's `vol=` key, written back to it), the selected one and the gizmo mode, and the
 * GrowthOverlay in the viewer. A gizmo drag regrows the tree on every move through `regrow`
 * (the scheduler is latest-wins, so only the newest shape is ever waited for).
 */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { Params, VolumeGroup, VolumeKind, VolumePrimitive } from '../core/types';
import { MAX_VOLUMES, newVolume } from '../core/volumes';
import { decodeVolumes, encodeVolumes, VOLUMES_KEY } from '../url/codec';
import { GrowthOverlay } from '../viewer/GrowthOverlay';
import type { TreeViewer } from '../viewer/TreeViewer';
import { installDebugHook } from './debugHook';

/** What the app and the Growth panel see of the editor. */
export interface GrowthEditor {
  volumes: VolumePrimitive[];
  selected: number | null;
  mode: 'translate' | 'scale';
  add(kind: VolumeKind, group: VolumeGroup): void;
  remove(index: number): void;
  select(index: number | null): void;
  setMode(mode: 'translate' | 'scale'): void;
  setGroup(index: number, group: VolumeGroup): void;
}

/**
 * `search` with its `vol=` entry replaced by `vol=<text>` (or removed when `text` is empty). Every
 * other entry is kept byte for byte: re-serialising the query (URLSearchParams) would re-encode
 * a hostile entry such as `%ZZ` into a valid `%25ZZ`, and the link's own notices would be lost
 * if the app read the URL after that.
 */
export function withVolumesQuery(search: string, text: string): string {
  const pieces = search
    .replace(/^\?/, '')
    .split('&')
    .filter((piece) => piece !== '' && piece.split('=', 1)[0] !== VOLUMES_KEY);
  if (text) pieces.push(`${VOLUMES_KEY}=${encodeURIComponent(text)}`);
  return pieces.length > 0 ? `?${pieces.join('&')}` : '';
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

/**
 * See the module comment. `volumesRef` holds the latest volumes (its initial value is the
 * same list as `initialVolumes` at first; the app reads it for every request); `regrow` requests a tree of the current
 * params with new volumes.
 */
export function useGrowthEditor(
  viewerRef: RefObject<TreeViewer | null>,
  params: Params | null,
  volumesRef: RefObject<VolumePrimitive[]>,
  initialVolumes: VolumePrimitive[],
  regrow: (volumes: VolumePrimitive[]) => void,
): GrowthEditor {
  const [volumes, setVolumesState] = useState<VolumePrimitive[]>(initialVolumes);
  const [selected, setSelected] = useState<number | null>(null);
  const [mode, setMode] = useState<'translate' | 'scale'>('translate');
  const overlayRef = useRef<GrowthOverlay | null>(null);
  const regrowRef = useRef(regrow);
  useEffect(() => {
    regrowRef.current = regrow;
  });

  const setVolumes = useCallback(
    (next: VolumePrimitive[], request: boolean) => {
      volumesRef.current = next;
      setVolumesState(next);
      if (request) regrowRef.current(next);
    },
    [volumesRef],
  );

  useEffect(() => {
    const viewer = viewerRef.current;
    if (!viewer) return;
    const overlay = new GrowthOverlay(viewer.overlayHost(), (index, volume) => {
      const next = volumesRef.current.slice();
      if (index >= next.length) return;
      next[index] = volume;
      setVolumes(next, true);
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
  }, [viewerRef, volumesRef, setVolumes]);

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

  const add = useCallback(
    (kind: VolumeKind, group: VolumeGroup) => {
      const current = volumesRef.current;
      if (current.length >= MAX_VOLUMES) return;
      setVolumes([...current, newVolume(kind, group, current.length)], true);
      setSelected(current.length);
    },
    [setVolumes, volumesRef],
  );

  const remove = useCallback(
    (index: number) => {
      setVolumes(
        volumesRef.current.filter((_, i) => i !== index),
        true,
      );
      setSelected(null);
    },
    [setVolumes, volumesRef],
  );

  const setGroup = useCallback(
    (index: number, group: VolumeGroup) => {
      setVolumes(
        volumesRef.current.map((v, i) => (i === index ? { ...v, group } : v)),
        true,
      );
    },
    [setVolumes, volumesRef],
  );

  return {
    volumes,
    selected,
    mode,
    add,
    remove,
    select: setSelected,
    setMode,
    setGroup,
  };
}
