/** Pointer input helpers for the games' canvases. DOM only: no renderer, no physics. */

/**
 * The pointer position in CSS px relative to `canvas`' top-left corner, written into `out` (also
 * returned). Camera conversion to metres is the renderer's (`camera.toWorldX`, `app.toNdc`).
 */
export function pointerOnCanvas<P extends { x: number; y: number }>(
  canvas: HTMLCanvasElement,
  event: PointerEvent | MouseEvent,
  out: P,
): P {
  const rect = canvas.getBoundingClientRect();
  out.x = event.clientX - rect.left;
  out.y = event.clientY - rect.top;
  return out;
}
