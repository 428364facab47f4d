// Replaying a multi-frame FOLD document in the folding manager: the states of `orikin simulate
// -o` (frame_time, seconds), of `orikin sequence -o` (orikin:time, folds) or of any file with
// several frames (one unit per frame), as GET /api/frames serves them. The slider, play and the
// number field run over the frames' times; between two frames the vertex positions are
// interpolated linearly; at a frame's time the state is the file's, exactly.

// Slider positions over the whole replay.
const STEPS = 1000;
// Playback at 1×: a timed replay (seconds) lasts this many seconds whatever its duration (a
// simulated fold takes milliseconds); sequence time runs at 0.25 fold per second as the
// sequence's slider does; untimed frames at 4 frames per second.
const PLAY_SECONDS = 4;
const RATE = { fold: 0.25, frame: 4 };
const UNIT_NAMES = ['frame', 's', 'fold'];

// GET /api/frames?binary=1 (little-endian float64): count, V, unit (0 frame, 1 s, 2 fold), first
// frame, 0 × 4; count times; count × 3V vertex coordinates.
export function decodeFrames(buffer) {
  const d = new Float64Array(buffer);
  const n = d[0], V = d[1];
  return {
    count: n,
    vertexCount: V,
    unit: UNIT_NAMES[d[2]] || 'frame',
    first: d[3],
    times: d.subarray(8, 8 + n),
    positions: d.subarray(8 + n, 8 + n + 3 * n * V),
  };
}

// The state at time t: {positions, k, s} with k the frame before t and s ∈ [0, 1) the way to
// the next (s = 0: frame k exactly, copied).
export function stateAt(fr, t) {
  const { times, count: n, vertexCount: V } = fr;
  const w = 3 * V;
  if (!(t > times[0])) return { positions: fr.positions.slice(0, w), k: 0, s: 0 };
  if (t >= times[n - 1]) return { positions: fr.positions.slice((n - 1) * w, n * w), k: n - 1, s: 0 };
  let lo = 0, hi = n - 1; // times[lo] <= t < times[hi]
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= t) lo = mid; else hi = mid;
  }
  const s = (t - times[lo]) / (times[hi] - times[lo]);
  const a = fr.positions.subarray(lo * w, (lo + 1) * w);
  if (s === 0) return { positions: a.slice(), k: lo, s: 0 };
  const b = fr.positions.subarray(hi * w, (hi + 1) * w);
  const p = new Float64Array(w);
  for (let i = 0; i < w; i++) p[i] = a[i] + s * (b[i] - a[i]);
  return { positions: p, k: lo, s };
}

function fmtTime(t, unit) {
  const x = +t.toPrecision(6);
  return unit === 's' ? `${x} s` : unit === 'fold' ? `T = ${x}` : `frame ${x}`;
}

// The folding manager's controls (the page's #t-slider, #t-value, #play, #speed, #t-label and
// #state3d) driven by a document's frames while no sequence has run.
export class FrameReplay {
  // hooks.show(positions, label): draw a state in the 3D view.
  constructor(api, $, hooks) {
    this.api = api;
    this.$ = $;
    this.hooks = hooks;
    this.frames = null;
    this.on = false;
    this.playing = false;
    this.t = 0;
    this.shown = null; // {t, k, s} of the state on screen
  }

  // Fetch the frames of the document (frameCount: its number of frames); none when it has one.
  async load(frameCount) {
    this.stop();
    this.frames = null;
    if (!(frameCount >= 2)) return;
    const fr = decodeFrames(await this.api.binary('frames', { binary: 1 }));
    if (fr.count >= 2) this.frames = fr; // else one state (a crease pattern and one frame)
  }

  get duration() { return this.frames ? this.frames.times[this.frames.count - 1] - this.frames.times[0] : 0; }

  // Take the timeline (want: no sequence holds it) or give it back. True when taken.
  setup(want) {
    const $ = this.$;
    const label = $('t-value').parentElement.firstChild;
    this.stop();
    this.on = !!(want && this.frames && this.duration > 0);
    if (!this.on) {
      label.textContent = 'T ';
      this.shown = null;
      return false;
    }
    const fr = this.frames;
    label.textContent = fr.unit === 's' ? 't (s) ' : fr.unit === 'fold' ? 'T ' : 'frame ';
    const slider = $('t-slider'), tv = $('t-value');
    slider.min = 0;
    slider.max = STEPS;
    slider.disabled = false;
    tv.disabled = false;
    tv.min = fr.times[0];
    tv.max = fr.times[fr.count - 1];
    $('play').disabled = false;
    this.show(fr.times[0]);
    return true;
  }

  // Show the state at time t (clamped to the frames' times).
  show(t) {
    if (!this.on) return;
    const fr = this.frames, $ = this.$;
    const t0 = fr.times[0], t1 = fr.times[fr.count - 1];
    t = Math.min(Math.max(t, t0), t1);
    const st = stateAt(fr, t);
    this.t = t;
    this.shown = { t, k: st.k, s: st.s };
    const frame = fr.first + st.k;
    const where = st.s === 0 ? `frame ${frame} of the file` : `between frames ${frame} and ${frame + 1} (interpolated)`;
    const text = `${fmtTime(t, fr.unit)}: ${where}`;
    $('t-label').textContent = text;
    $('t-value').value = String(+t.toPrecision(12));
    $('t-slider').value = String(Math.round(((t - t0) / (t1 - t0)) * STEPS));
    this.hooks.show(st.positions, text);
  }

  // The slider's position v (0 … STEPS).
  slide(v) {
    this.stop();
    const fr = this.frames;
    this.show(fr.times[0] + (this.duration * v) / STEPS);
  }

  // The document frame nearest to the state shown (what collide and export take).
  stateRef() {
    if (!this.shown) return { frame: 0 };
    return { frame: this.frames.first + this.shown.k + (this.shown.s >= 0.5 ? 1 : 0) };
  }

  stop() {
    if (!this.playing) return;
    this.playing = false;
    this.$('play').textContent = '▶';
  }

  togglePlay() {
    if (!this.on) return;
    if (this.playing) { this.stop(); return; }
    const fr = this.frames, $ = this.$;
    const t0 = fr.times[0], t1 = fr.times[fr.count - 1];
    const rate = fr.unit === 's' ? this.duration / PLAY_SECONDS : RATE[fr.unit];
    this.playing = true;
    $('play').textContent = '❚❚';
    let t = this.t >= t1 ? t0 : this.t;
    let last = performance.now();
    const tick = (now) => {
      if (!this.playing || !this.on) return;
      t = Math.min(t1, t + (Math.max(0, now - last) / 1000) * rate * +$('speed').value);
      last = Math.max(last, now);
      this.show(t);
      if (t >= t1) { this.stop(); return; }
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }
}
