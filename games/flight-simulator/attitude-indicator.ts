/**
 * The flight simulator's attitude indicator (the artificial horizon), drawn on a canvas over the
 * top of the scene in the cockpit view: sky over ground split by the horizon, turned by the bank and
 * moved by the pitch, a pitch ladder every 10 degrees, the bank scale with its pointer, and the
 * fixed aircraft symbol. DOM only.
 */

/** An attitude indicator over the scene. */
export interface AttitudeIndicator {
  /** The canvas (labelled "attitude indicator"). */
  readonly canvas: HTMLCanvasElement;
  /** Shows or hides it. */
  show(visible: boolean): void;
  /** Draws pitch and bank, degrees (+ nose up, + right wing down). */
  draw(pitch: number, roll: number): void;
}

/** Creates the indicator, `size` CSS px square, centred at the top of `stage` and hidden. */
export function createAttitudeIndicator(stage: HTMLElement, size: number): AttitudeIndicator {
  // The ladder spans about 68 degrees of pitch across the dial.
  const pitchPx = size / 68;
  const canvas = document.createElement('canvas');
  canvas.width = size * devicePixelRatio;
  canvas.height = size * devicePixelRatio;
  canvas.dataset.sceneOverlay = '';
  canvas.setAttribute('aria-label', 'attitude indicator');
  canvas.style.cssText = `position: absolute; left: 50%; top: 8px; width: ${size}px; height: ${size}px; transform: translateX(-50%); pointer-events: none; z-index: 5; display: none`;
  stage.append(canvas);

  /** Draws the dial for `pitch` and `roll`, degrees. */
  function draw(pitch: number, roll: number): void {
    const g = canvas.getContext('2d');
    if (!g) return;
    const S = size,
      c = S / 2;
    g.setTransform(devicePixelRatio, 0, 0, devicePixelRatio, 0, 0);
    g.clearRect(0, 0, S, S);
    g.save();
    g.beginPath();
    g.arc(c, c, c - 2, 0, 2 * Math.PI);
    g.clip();
    g.translate(c, c);
    g.rotate((-roll * Math.PI) / 180);
    const dy = pitch * pitchPx;
    g.fillStyle = '#2a6fb8';
    g.fillRect(-S, -2 * S + dy, 2 * S, 2 * S);
    g.fillStyle = '#6b4526';
    g.fillRect(-S, dy, 2 * S, 2 * S);
    g.strokeStyle = '#ffffff';
    g.lineWidth = 2;
    g.beginPath();
    g.moveTo(-S, dy);
    g.lineTo(S, dy);
    g.stroke();
    g.lineWidth = 1;
    g.font = 'bold 10px system-ui, sans-serif';
    g.fillStyle = '#ffffff';
    for (let p = -30; p <= 30; p += 10) {
      if (p === 0) continue;
      const y = dy - p * pitchPx,
        half = p % 20 === 0 ? 22 : 14;
      g.beginPath();
      g.moveTo(-half, y);
      g.lineTo(half, y);
      g.stroke();
      g.fillText(String(Math.abs(p)), half + 3, y + 3);
    }
    g.restore();
    g.strokeStyle = '#ffffff';
    g.lineWidth = 2;
    for (const b of [-60, -30, -20, -10, 0, 10, 20, 30, 60]) {
      const a = ((b - 90) * Math.PI) / 180,
        r1 = c - 4,
        r2 = c - (b % 30 === 0 ? 14 : 9);
      g.beginPath();
      g.moveTo(c + r1 * Math.cos(a), c + r1 * Math.sin(a));
      g.lineTo(c + r2 * Math.cos(a), c + r2 * Math.sin(a));
      g.stroke();
    }
    const pa = ((-roll - 90) * Math.PI) / 180;
    g.fillStyle = '#ffd166';
    g.beginPath();
    g.moveTo(c + (c - 16) * Math.cos(pa), c + (c - 16) * Math.sin(pa));
    g.lineTo(c + (c - 26) * Math.cos(pa + 0.09), c + (c - 26) * Math.sin(pa + 0.09));
    g.lineTo(c + (c - 26) * Math.cos(pa - 0.09), c + (c - 26) * Math.sin(pa - 0.09));
    g.fill();
    g.strokeStyle = '#ffd166';
    g.lineWidth = 4;
    g.beginPath();
    g.moveTo(c - 0.28 * S, c);
    g.lineTo(c - 14, c);
    g.lineTo(c - 8, c + 7);
    g.moveTo(c + 0.28 * S, c);
    g.lineTo(c + 14, c);
    g.lineTo(c + 8, c + 7);
    g.stroke();
    g.fillStyle = '#ffd166';
    g.beginPath();
    g.arc(c, c, 3, 0, 2 * Math.PI);
    g.fill();
    g.strokeStyle = '#0b0f14';
    g.lineWidth = 3;
    g.beginPath();
    g.arc(c, c, c - 2, 0, 2 * Math.PI);
    g.stroke();
  }
  return {
    canvas,
    show(visible) {
      canvas.style.display = visible ? 'block' : 'none';
    },
    draw,
  };
}
