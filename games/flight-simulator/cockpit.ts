/**
 * The flight simulator's cockpit, drawn over the scene in the cockpit view: the canopy's frame (a
 * bow across the top, a post down each side) and the instrument panel across the bottom, with round
 * gauges: airspeed, altimeter, heading (a compass card turning under a fixed lubber line, with a
 * green bug at the next ring's heading) and
 * vertical speed, and the engine's throttle as a bar. The attitude indicator (./attitude-indicator.ts)
 * is placed in the middle of the panel by the page. Each gauge has its name and its reading in digits
 * under the needle, in white on the panel's dark grey (contrast above 12:1). DOM only (a 2D canvas).
 */

/** What the gauges show: m/s, m, degrees, m/s and a fraction. */
export interface CockpitReadings {
  /** Airspeed, m/s (the dial reads 0 to 250). */
  speed: number;
  /** Altitude above sea level, m (the needle goes round every 1,000 m). */
  altitude: number;
  /** Heading, degrees, 0 to 360. */
  heading: number;
  /**
   * The heading to the next ring, degrees, 0 to 360 (absent: none): a bug on the compass's rim (the
   * narrow screen's glare shield names it), so a turn is flown until the bug is under the lubber line.
   */
  ring?: number;
  /** Vertical speed, m/s, + up (the dial reads -30 to 30). */
  climb: number;
  /** Throttle, fraction of full, [0, 1]. */
  throttle: number;
}

/** A cockpit overlay (see the file's header). */
export interface Cockpit {
  /** The canvas, as large as the stage (labelled "cockpit instruments"). */
  readonly canvas: HTMLCanvasElement;
  /** Shows or hides it. */
  show(visible: boolean): void;
  /** Draws the frame and the gauges for `r`. */
  draw(r: CockpitReadings): void;
  /** The panel's top, CSS px from the stage's top (0 before the first draw). */
  panelTop(): number;
  /** Where the attitude indicator goes: its centre (CSS px in the stage) and size (px). */
  attitudeSlot(): { x: number; y: number; size: number };
  /** The gauges drawn last: name, centre and radius (CSS px in the stage), and the value shown. */
  gauges(): { name: string; x: number; y: number; r: number; value: number }[];
}

const DEG = Math.PI / 180;

/**
 * Creates the cockpit over `stage`, hidden. `attitudeSize` is the attitude indicator's size (CSS
 * px): the panel is made tall enough to hold it. @throws RangeError unless attitudeSize > 0.
 */
export function createCockpit(stage: HTMLElement, attitudeSize: number): Cockpit {
  if (!(attitudeSize > 0)) throw new RangeError(`createCockpit: attitudeSize must be > 0 px, got ${attitudeSize}`);
  const canvas = document.createElement('canvas');
  canvas.dataset.sceneOverlay = '';
  canvas.setAttribute('aria-label', 'cockpit instruments');
  canvas.style.cssText = 'position: absolute; left: 0; top: 0; width: 100%; height: 100%; pointer-events: none; z-index: 4; display: none';
  stage.append(canvas);
  let top = 0;
  let slot = { x: 0, y: 0, size: attitudeSize };
  let drawn: { name: string; x: number; y: number; r: number; value: number }[] = [];

  /** A round instrument's face: a dark disc of radius r (px) at (x, y) with a grey rim. */
  function dialFace(g: CanvasRenderingContext2D, x: number, y: number, r: number): void {
    g.fillStyle = '#0c0f13';
    g.beginPath();
    g.arc(x, y, r, 0, 2 * Math.PI);
    g.fill();
    g.strokeStyle = '#5a6270';
    g.lineWidth = 3;
    g.stroke();
  }

  /** A round gauge at (x, y) of radius r: its face, ticks from `from` to `to` (values, with `ticks` steps, at angles a0 to a1, rad), the needle at `value`, the digits `text` and its name. */
  function gauge(
    g: CanvasRenderingContext2D,
    name: string,
    x: number,
    y: number,
    r: number,
    o: { from: number; to: number; ticks: number; a0: number; a1: number; value: number; text: string },
  ): void {
    dialFace(g, x, y, r);
    const angle = (v: number): number => o.a0 + ((o.a1 - o.a0) * (v - o.from)) / (o.to - o.from);
    g.strokeStyle = '#e8ecf1';
    g.fillStyle = '#e8ecf1';
    g.font = `${Math.max(8, Math.round(r * 0.2))}px system-ui, sans-serif`;
    g.textAlign = 'center';
    g.textBaseline = 'middle';
    for (let k = 0; k <= o.ticks; k++) {
      const v = o.from + ((o.to - o.from) * k) / o.ticks,
        a = angle(v);
      const long = k % 2 === 0;
      g.lineWidth = long ? 2 : 1;
      g.beginPath();
      g.moveTo(x + Math.cos(a) * r * 0.92, y + Math.sin(a) * r * 0.92);
      g.lineTo(x + Math.cos(a) * r * (long ? 0.74 : 0.82), y + Math.sin(a) * r * (long ? 0.74 : 0.82));
      g.stroke();
    }
    const a = angle(Math.max(o.from, Math.min(o.to, o.value)));
    g.strokeStyle = '#ffd166';
    g.lineWidth = 3;
    g.lineCap = 'round';
    g.beginPath();
    g.moveTo(x - Math.cos(a) * r * 0.12, y - Math.sin(a) * r * 0.12);
    g.lineTo(x + Math.cos(a) * r * 0.78, y + Math.sin(a) * r * 0.78);
    g.stroke();
    g.fillStyle = '#ffd166';
    g.beginPath();
    g.arc(x, y, r * 0.07, 0, 2 * Math.PI);
    g.fill();
    // The reading under the hub, the name under the gauge.
    g.fillStyle = '#ffffff';
    g.font = `700 ${Math.max(11, Math.round(r * 0.26))}px ui-monospace, Menlo, Consolas, monospace`;
    g.fillText(o.text, x, y + r * 0.42);
    label(g, name, x, y, r);
  }

  /** A gauge's name under it, on the panel. */
  function label(g: CanvasRenderingContext2D, name: string, x: number, y: number, r: number): void {
    g.fillStyle = '#c7d3e0';
    g.font = `600 ${Math.max(10, Math.round(r * 0.17))}px system-ui, sans-serif`;
    g.textAlign = 'center';
    g.textBaseline = 'top';
    g.fillText(name, x, y + r + 3);
    g.textBaseline = 'middle';
  }

  /** The compass: a card marked every 30 degrees (N, E, S, W) turned by the heading under a fixed mark at the top, and the ring's bug (`ring`, degrees) on its rim. */
  function compass(g: CanvasRenderingContext2D, x: number, y: number, r: number, heading: number, ring?: number): void {
    dialFace(g, x, y, r);
    g.textAlign = 'center';
    g.textBaseline = 'middle';
    for (let d = 0; d < 360; d += 10) {
      const a = (d - heading - 90) * DEG;
      const major = d % 30 === 0;
      g.strokeStyle = '#e8ecf1';
      g.lineWidth = major ? 2 : 1;
      g.beginPath();
      g.moveTo(x + Math.cos(a) * r * 0.92, y + Math.sin(a) * r * 0.92);
      g.lineTo(x + Math.cos(a) * r * (major ? 0.76 : 0.84), y + Math.sin(a) * r * (major ? 0.76 : 0.84));
      g.stroke();
      if (major) {
        const name = { 0: 'N', 90: 'E', 180: 'S', 270: 'W' }[d] ?? String(d / 10);
        g.fillStyle = d % 90 === 0 ? '#ffd166' : '#e8ecf1';
        g.font = `700 ${Math.max(8, Math.round(r * 0.18))}px system-ui, sans-serif`;
        g.fillText(name, x + Math.cos(a) * r * 0.6, y + Math.sin(a) * r * 0.6);
      }
    }
    if (ring !== undefined && Number.isFinite(ring)) {
      // The ring's bug: a green notch on the card's rim at the ring's heading, turning with the card.
      const a = (ring - heading - 90) * DEG,
        c = Math.cos(a),
        sn = Math.sin(a);
      g.fillStyle = '#5dff8a';
      g.strokeStyle = '#0c0f13';
      g.lineWidth = 1.5;
      g.beginPath();
      g.moveTo(x + c * r * 0.74, y + sn * r * 0.74);
      g.lineTo(x + c * r * 0.98 - sn * r * 0.13, y + sn * r * 0.98 + c * r * 0.13);
      g.lineTo(x + c * r * 0.98 + sn * r * 0.13, y + sn * r * 0.98 - c * r * 0.13);
      g.closePath();
      g.fill();
      g.stroke();
    }
    // The lubber line: a fixed triangle at the top.
    g.fillStyle = '#ffd166';
    g.beginPath();
    g.moveTo(x, y - r * 0.97);
    g.lineTo(x - r * 0.09, y - r * 0.78);
    g.lineTo(x + r * 0.09, y - r * 0.78);
    g.fill();
    g.fillStyle = '#ffffff';
    g.font = `700 ${Math.max(10, Math.round(r * 0.24))}px ui-monospace, Menlo, Consolas, monospace`;
    g.fillText(`${String(Math.round(heading) % 360).padStart(3, '0')}°`, x, y);
    label(g, 'HEADING', x, y, r);
  }

  function draw(rd: CockpitReadings): void {
    const w = stage.clientWidth,
      h = stage.clientHeight;
    if (!(w > 0 && h > 0)) return;
    const dpr = devicePixelRatio || 1;
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
    }
    const g = canvas.getContext('2d');
    if (!g) return;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, w, h);
    const narrow = w < 560;
    // The panel: tall enough for the attitude indicator and a margin; a glare shield curving over it.
    const panelH = attitudeSize + (narrow ? 26 : 34);
    top = h - panelH;
    // The canopy: a bow across the top and a post down each side to the panel.
    g.fillStyle = '#1b2028';
    const bow = Math.max(10, h * 0.035),
      post = Math.max(12, w * 0.035);
    g.beginPath();
    g.moveTo(0, 0);
    g.lineTo(w, 0);
    g.lineTo(w, bow);
    g.quadraticCurveTo(w / 2, bow * 2.2, 0, bow);
    g.closePath();
    g.fill();
    for (const side of [0, 1]) {
      g.beginPath();
      const x0 = side ? w : 0,
        dir = side ? -1 : 1;
      g.moveTo(x0, bow);
      g.lineTo(x0 + dir * post * 0.6, bow);
      g.lineTo(x0 + dir * post * 2.4, top);
      g.lineTo(x0, top);
      g.closePath();
      g.fill();
    }
    const grad = g.createLinearGradient(0, top - 14, 0, h);
    grad.addColorStop(0, '#2c333e');
    grad.addColorStop(0.12, '#232932');
    grad.addColorStop(1, '#171b21');
    g.fillStyle = grad;
    g.beginPath();
    g.moveTo(0, top + 8);
    g.quadraticCurveTo(w / 2, top - 22, w, top + 8);
    g.lineTo(w, h);
    g.lineTo(0, h);
    g.closePath();
    g.fill();
    g.strokeStyle = '#0b0e12';
    g.lineWidth = 2;
    g.beginPath();
    g.moveTo(0, top + 8);
    g.quadraticCurveTo(w / 2, top - 22, w, top + 8);
    g.stroke();
    // The gauges either side of the attitude indicator in the middle, their names under them.
    const cy = top + panelH / 2 - 2;
    const r = Math.min(narrow ? 0.42 * attitudeSize : 0.46 * attitudeSize, (w - attitudeSize) / (narrow ? 4.6 : 9));
    slot = { x: w / 2, y: cy, size: attitudeSize };
    const gap = attitudeSize / 2 + r + (narrow ? 10 : 18);
    drawn = [];
    const speed = {
      from: 0,
      to: 250,
      ticks: 10,
      a0: 135 * DEG,
      a1: 405 * DEG,
      value: rd.speed,
      text: `${Math.round(rd.speed)}`,
    };
    const alt = {
      from: 0,
      to: 1000,
      ticks: 10,
      a0: -90 * DEG,
      a1: 270 * DEG,
      value: ((rd.altitude % 1000) + 1000) % 1000,
      text: `${Math.round(rd.altitude)}`,
    };
    gauge(g, 'SPEED m/s', w / 2 - gap, cy, r, speed);
    drawn.push({ name: 'speed', x: w / 2 - gap, y: cy, r, value: rd.speed });
    gauge(g, 'ALT m', w / 2 + gap, cy, r, alt);
    drawn.push({ name: 'altitude', x: w / 2 + gap, y: cy, r, value: rd.altitude });
    if (!narrow) {
      const far = gap + 2 * r + 16;
      compass(g, w / 2 - far, cy, r, rd.heading, rd.ring);
      drawn.push({ name: 'heading', x: w / 2 - far, y: cy, r, value: rd.heading });
      gauge(g, 'CLIMB m/s', w / 2 + far, cy, r, {
        from: -30,
        to: 30,
        ticks: 6,
        a0: 180 * DEG,
        a1: 360 * DEG,
        value: rd.climb,
        text: `${rd.climb >= 0 ? '+' : ''}${rd.climb.toFixed(0)}`,
      });
      drawn.push({ name: 'climb', x: w / 2 + far, y: cy, r, value: rd.climb });
    } else {
      // On a narrow screen the heading is digits on the glare shield.
      g.fillStyle = '#ffffff';
      g.font = '700 13px ui-monospace, Menlo, Consolas, monospace';
      g.textAlign = 'center';
      const hdg = (d: number) => `${String(Math.round(d) % 360).padStart(3, '0')}°`;
      g.fillText(`HDG ${hdg(rd.heading)}${rd.ring === undefined ? '' : ` · RING ${hdg(rd.ring)}`}`, w / 2, top - 2);
      drawn.push({ name: 'heading', x: w / 2, y: top - 2, r: 0, value: rd.heading });
    }
    // The throttle: a bar at the panel's right edge (the left one on a narrow screen would meet the speed gauge).
    const barH = panelH - 30,
      barX = w - (narrow ? 14 : 26),
      barY = top + 16;
    g.fillStyle = '#0c0f13';
    g.fillRect(barX - 5, barY, 10, barH);
    g.fillStyle = '#7ee787';
    const t = Math.max(0, Math.min(1, rd.throttle));
    g.fillRect(barX - 5, barY + barH * (1 - t), 10, barH * t);
    g.strokeStyle = '#5a6270';
    g.lineWidth = 1;
    g.strokeRect(barX - 5, barY, 10, barH);
    drawn.push({ name: 'throttle', x: barX, y: barY + barH / 2, r: 5, value: rd.throttle });
  }

  return {
    canvas,
    show(visible) {
      canvas.style.display = visible ? 'block' : 'none';
    },
    draw,
    panelTop: () => top,
    attitudeSlot: () => ({ ...slot }),
    gauges: () => drawn.map((d) => ({ ...d })),
  };
}
