/** Mounts the three.js TreeViewer into a full-size div and exposes it through a ref. */
import { useEffect, useRef, type RefObject } from 'react';
import { TreeViewer } from '../viewer/TreeViewer';

/** The 3D view; the viewer instance is written to `viewerRef` while mounted. */
export function Viewport({ viewerRef }: { viewerRef: RefObject<TreeViewer | null> }) {
  const containerRef = useRef<HTMLDivElement>(null);
  useEffect(() => {
    const container = containerRef.current;
    if (!container) return;
    const viewer = new TreeViewer(container);
    viewerRef.current = viewer;
    return () => {
      if (viewerRef.current === viewer) viewerRef.current = null;
      viewer.dispose();
    };
  }, [viewerRef]);
  return <div className="viewport" ref={containerRef} data-testid="viewport" />;
}
