/**
 * Closes an open `<details>` menu the way menus close: on Escape (focus back on its summary) and
 * on a press anywhere outside it. The listeners look at the menu when the key or press comes, so
 * an Escape right after opening closes it too.
 */
import { useEffect, type RefObject } from 'react';

export function useDismiss(ref: RefObject<HTMLDetailsElement | null>): void {
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      const menu = ref.current;
      if (e.key !== 'Escape' || !menu?.open) return;
      menu.open = false;
      menu.querySelector('summary')?.focus();
    };
    const onPointer = (e: PointerEvent) => {
      const menu = ref.current;
      if (menu?.open && !(e.target instanceof Node && menu.contains(e.target))) menu.open = false;
    };
    document.addEventListener('keydown', onKey);
    document.addEventListener('pointerdown', onPointer, true);
    return () => {
      document.removeEventListener('keydown', onKey);
      document.removeEventListener('pointerdown', onPointer, true);
    };
  }, [ref]);
}
