// The folding manager (thesis ch. 9.7): the folds of the sequence (added from the fold panel,
// removed, run again), the one slider over the sequence time T with play and the number field,
// every instant restored exactly by the server, the plot's cursor. ctx: {state, store, $, api,
// v3, plot, replay, message, action, refresh, collideOptions, clearCollision, showContact,
// clearFold, foldBody}.
import { decodeState } from './api.js';
import { fmt } from './document.js';
import { foldItemText } from './format.js';
import { sequenceFold, sequenceJson as buildSequenceJson } from './requests.js';

// Sequence time per second of playback at 1×.
const PLAY_RATE = 0.25;

export function createSequence(ctx) {
  const { state, $, message, action } = ctx;
  function sequenceJson(folds) {
    return buildSequenceJson(state.session.file, folds);
  }

  async function runSequence(folds, label) {
    if (!folds.length) {
      state.folds = [];
      ctx.store.set({ sequence: null });
      setupTimeline();
      return;
    }
    const r = await ctx.api.compute(label || 'sequence', () => ctx.api.post('sequence', sequenceJson(folds), ctx.collideOptions()));
    state.folds = folds;
    ctx.store.set({ sequence: r });
    await ctx.refresh();
    setupTimeline();
    if (r.collision) message(`collision: ${r.reason} (the sequence stops before it)`, true);
    else if (!r.valid) message(`fold ${r.failed_fold} is ${r.verdict}: ${r.reason}`, true);
    // a sequence that recorded no state or no time (its first fold failed, or did not move from
    // its start) has no instant to show: asking for one would only add a second, stale error
    // ("t: time 0 is outside [0, 0]")
    if (r.frames.length && r.duration > 0) await showTime(lastCleanT());
    if (r.collision) await ctx.showContact('sequence');
  }

  function renderFolds() {
    const ol = $('folds');
    ol.replaceChildren();
    const r = state.sequence;
    state.folds.forEach((f, i) => {
      const li = document.createElement('li');
      const failed = r && r.failed_fold === i + 1;
      li.className = failed ? 'failed' : '';
      li.textContent = foldItemText(f) + (failed ? ` — ${r.verdict}` : '');
      const x = document.createElement('button');
      x.className = 'small';
      x.textContent = '×';
      x.title = 'Remove this fold (and run the sequence again)';
      x.onclick = () => action(() => runSequence(state.folds.filter((_, k) => k !== i), 'sequence'));
      li.appendChild(x);
      ol.appendChild(li);
    });
  }

  function setupTimeline() {
    const r = state.sequence;
    const slider = $('t-slider'), tv = $('t-value');
    const duration = r ? r.duration : 0;
    const steps = state.grid > 0 ? state.grid : 200;
    // a sequence that collides is clean before its first contact only (as orikin sequence --at)
    const contactT = r && state.session && state.session.sequence ? state.session.sequence.collision_t : null;
    state.seqLimit = contactT !== null && contactT !== undefined ? contactT : duration;
    slider.min = 0;
    slider.max = contactT !== null && contactT !== undefined ? Math.max(0, Math.ceil(contactT * steps) - 1) : Math.round(duration * steps);
    slider.disabled = !r || duration === 0;
    tv.disabled = slider.disabled;
    tv.max = state.seqLimit;
    $('play').disabled = slider.disabled;
    $('show-seq-contact').hidden = !(r && r.collision);
    ctx.plot.setRecord(r, state.doc ? state.doc.assignment : [], contactT);
    renderFolds();
    // the folds are kept when the pattern changes; their record is not (its indices may be stale)
    $('run-seq').hidden = !!r || state.folds.length === 0;
    if (ctx.replay.setup(!r)) return;
    if (!r) {
      $('t-label').textContent = 'no sequence: specify a fold above and add it';
      $('t-value').value = '0';
      slider.value = '0';
      ctx.plot.setCursor(null);
    }
  }

  function sliderSteps() {
    return state.grid > 0 ? state.grid : 200;
  }

  // The last instant the slider reaches: the end, or the last grid point before the first contact.
  function lastCleanT() {
    return +$('t-slider').max / sliderSteps();
  }

  // Show the state at time T (exact, from the server); requests never pile up: while one is in
  // flight only the latest wanted T is remembered.
  async function showTime(t) {
    state.targetT = Math.min(Math.max(t, 0), lastCleanT());
    if (state.inflight) return;
    state.inflight = true;
    try {
      while (state.targetT !== null) {
        const want = state.targetT;
        state.targetT = null;
        const t0 = performance.now();
        const st = decodeState(await ctx.api.binary('sequence/at', { t: want, binary: 1 }));
        state.stats.latency.push(performance.now() - t0);
        if (state.stats.latency.length > 500) state.stats.latency.shift();
        ctx.v3.setPositions(st.positions);
        if (state.shown === 'contact') ctx.clearCollision();
        state.stats.states++;
        state.t = want;
        state.shownT = want;
        state.shown = 'sequence';
        state.shownAngles = st.angles;
        ctx.plot.setCursor(want, st.angles);
        // a fold toward the targets has no drive angle (NaN): its time is its progress
        const at = Number.isNaN(st.drive_deg) ? `${fmt(100 * (want - (st.fold - 1)), 4)} % toward the targets` : `drive ${fmt(st.drive_deg, 4)}°`;
        const label = `T = ${fmt(want, 4)}: fold ${st.fold}, ${at}, residual ${st.residual.toExponential(1)}`;
        $('t-label').textContent = label;
        $('state3d').textContent = label;
        $('t-value').value = String(+want.toFixed(10));
        $('t-slider').value = String(Math.round(want * sliderSteps()));
      }
    } catch (e) {
      message(e.message, true);
      state.targetT = null;
    } finally {
      state.inflight = false;
    }
  }

  async function addFold() {
    await action(async () => {
      const b = ctx.foldBody();
      const fold = sequenceFold(b, `fold ${state.folds.length + 1}`);
      await runSequence(state.folds.concat([fold]), 'sequence');
      ctx.clearFold();
      message(`fold ${state.folds.length} added: the next fold starts where it ends`);
    });
  }

  function togglePlay() {
    if (!state.sequence) return ctx.replay.togglePlay();
    state.playing = !state.playing;
    $('play').textContent = state.playing ? '❚❚' : '▶';
    if (!state.playing) return;
    const duration = lastCleanT();
    let t = state.t >= duration ? 0 : state.t;
    let last = performance.now();
    const tick = (now) => {
      if (!state.playing) return;
      // an animation frame's time may precede the moment play was pressed: never step back
      t = Math.min(duration, Math.max(0, t + (Math.max(0, now - last) / 1000) * PLAY_RATE * +$('speed').value));
      last = Math.max(last, now);
      // on the grid of the scrubbing cache: every state is exact and served at once
      const k = Math.round(t * sliderSteps());
      showTime(k / sliderSteps());
      if (t >= duration) {
        state.playing = false;
        $('play').textContent = '▶';
        return;
      }
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  return { sequenceJson, runSequence, setupTimeline, sliderSteps, lastCleanT, showTime, addFold, togglePlay };
}
