// The folding manager's plot: every crease angle that moves, against the sequence time T,
// from the recorded states (exact), with the cursor at the current instant and its angles, and
// the first contact of a sequence that collides.

// Above this many moving creases the cursor shows no dots (they would hide each other anyway).
const CURSOR_DOTS_MAX = 400;
const COLORS = { M: '#d7263d', V: '#1b6ef3', U: '#6f6f6f', F: '#9a9a9a' };

export class Plot {
  constructor(canvas) {
    this.canvas = canvas;
    this.record = null;
    this.assignment = [];
    this.cursor = null; // {t, angles}
    this.base = null;   // the curves, drawn once per record into an offscreen canvas
    new ResizeObserver(() => { this.base = null; this.draw(); }).observe(canvas);
  }

  setRecord(record, assignment, contactT = null) {
    this.record = record;
    this.contactT = contactT;
    this.assignment = assignment || [];
    this.base = null;
    // creases whose angle changes anywhere
    this.moving = [];
    if (record && record.frames.length) {
      const f0 = record.frames[0].fold_angles_deg;
      for (let e = 0; e < f0.length; e++)
        if (record.frames.some((fr) => fr.fold_angles_deg[e] !== f0[e])) this.moving.push(e);
    }
    this.draw();
  }

  setCursor(t, angles) {
    this.cursor = t === null ? null : { t, angles };
    this.draw();
  }

  geometry() {
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(this.canvas.clientWidth * dpr)), h = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
    const pad = { l: 34 * dpr, r: 8 * dpr, t: 6 * dpr, b: 16 * dpr };
    const T = this.record ? Math.max(this.record.duration, 1e-9) : 1;
    const x = (t) => pad.l + (w - pad.l - pad.r) * (t / T);
    const y = (a) => pad.t + (h - pad.t - pad.b) * (1 - (a + 180) / 360);
    return { w, h, dpr, pad, x, y, T };
  }

  drawBase(g) {
    const c = document.createElement('canvas');
    c.width = g.w; c.height = g.h;
    const ctx = c.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, g.w, g.h);
    ctx.font = `${10 * g.dpr}px system-ui, sans-serif`;
    ctx.fillStyle = '#6b717a';
    ctx.strokeStyle = '#e6e3dc';
    ctx.lineWidth = g.dpr;
    for (const a of [-180, -90, 0, 90, 180]) {
      ctx.beginPath(); ctx.moveTo(g.pad.l, g.y(a)); ctx.lineTo(g.w - g.pad.r, g.y(a)); ctx.stroke();
      ctx.fillText(String(a) + '°', 2 * g.dpr, g.y(a) + 3 * g.dpr);
    }
    for (let k = 0; k <= g.T; k++) {
      ctx.beginPath(); ctx.moveTo(g.x(k), g.pad.t); ctx.lineTo(g.x(k), g.h - g.pad.b); ctx.stroke();
      ctx.fillText('T=' + k, g.x(k) - (k === 0 ? 0 : 10 * g.dpr), g.h - 4 * g.dpr);
    }
    if (this.record) {
      const frames = this.record.frames;
      ctx.lineWidth = 1.5 * g.dpr;
      for (const e of this.moving) {
        ctx.strokeStyle = COLORS[this.assignment[e]] || '#444';
        ctx.beginPath();
        frames.forEach((fr, i) => {
          const px = g.x(fr.t), py = g.y(fr.fold_angles_deg[e]);
          if (i === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
        });
        ctx.stroke();
      }
      if (this.contactT !== null && this.contactT !== undefined) {
        ctx.strokeStyle = '#c0392b';
        ctx.setLineDash([4 * g.dpr, 3 * g.dpr]);
        ctx.beginPath(); ctx.moveTo(g.x(this.contactT), g.pad.t); ctx.lineTo(g.x(this.contactT), g.h - g.pad.b); ctx.stroke();
        ctx.setLineDash([]);
        ctx.fillStyle = '#c0392b';
        ctx.fillText('contact', g.x(this.contactT) + 3 * g.dpr, g.pad.t + 9 * g.dpr);
      }
    }
    return c;
  }

  draw() {
    const g = this.geometry();
    if (this.canvas.width !== g.w || this.canvas.height !== g.h) {
      this.canvas.width = g.w; this.canvas.height = g.h;
      this.base = null;
    }
    if (!this.base) this.base = this.drawBase(g);
    const ctx = this.canvas.getContext('2d');
    ctx.drawImage(this.base, 0, 0);
    if (this.cursor && this.record) {
      const px = g.x(this.cursor.t);
      ctx.strokeStyle = '#22262b';
      ctx.lineWidth = g.dpr;
      ctx.beginPath(); ctx.moveTo(px, g.pad.t); ctx.lineTo(px, g.h - g.pad.b); ctx.stroke();
      if (this.cursor.angles && this.moving.length <= CURSOR_DOTS_MAX) {
        for (const e of this.moving) {
          ctx.fillStyle = COLORS[this.assignment[e]] || '#444';
          ctx.beginPath();
          ctx.arc(px, g.y(this.cursor.angles[e]), 2.5 * g.dpr, 0, 2 * Math.PI);
          ctx.fill();
        }
      }
    }
  }
}
