/**
 * The Age timeline's play button (at the top of the Tree section): it grows the tree from a
 * seedling to its Mature Age, a step of Age each frame as a slider drag does (previews while it
 * plays), then the full tree. Pressing it again stops where the tree is.
 */
import { useEffect, useRef, useState } from 'react';
import type { Params, ParamSpec } from 'sylva-trees/core';
import { ageAt } from './agePlay';

interface Props {
  params: Params;
  onChange: (id: ParamSpec['id'], value: number, interactive?: boolean) => void;
}

/** See the module comment. */
export function AgePlayer({ params, onChange }: Props) {
  const [playing, setPlaying] = useState(false);
  const mature = params.maturity ?? 40;
  const latest = useRef({ onChange });
  useEffect(() => {
    latest.current = { onChange };
  });

  useEffect(() => {
    if (!playing) return;
    const start = performance.now();
    let frame = 0;
    let shown = -1;
    const tick = (now: number) => {
      const { age, done } = ageAt(now - start, mature);
      if (done) {
        shown = age;
        latest.current.onChange('age', age, false);
        setPlaying(false);
        return;
      }
      if (age !== shown) latest.current.onChange('age', age, true);
      shown = age;
      frame = requestAnimationFrame(tick);
    };
    frame = requestAnimationFrame(tick);
    return () => {
      cancelAnimationFrame(frame);
      // Stopped early: the full tree at the Age reached.
      if (shown >= 0 && shown !== mature) latest.current.onChange('age', shown, false);
    };
  }, [playing, mature]);

  return (
    <div className="param-row age-player">
      <button
        type="button"
        data-testid="age-play"
        aria-pressed={playing}
        title={`Grow the tree from a seedling to its Mature Age (${mature} years)`}
        onClick={() => setPlaying((p) => !p)}
      >
        {playing ? '■ Stop' : '▶ Grow from seedling'}
      </button>
    </div>
  );
}
