// Texts the page shows for folds and states. Pure.
import { fmt } from './document.js';

// The default output spacing of a fold (degrees), as the CLI's --step.
export const DEFAULT_STEP_DEG = 10;

// One fold of the sequence, as the folds list names it. A hand-written SEQ.json may leave out
// the step (the CLI's default then) or the fixed face (the CLI's default face).
export function foldItemText(f) {
  const what = f.percent !== undefined && f.percent !== null
    ? `${fmt(f.percent)} % of the way toward the targets`
    : `drive ${f.drive} to ${fmt(f.to)}°`;
  const fix = f.fix === undefined || f.fix === null ? 'default fixed face' : `fix ${f.fix}`;
  const step = f.step === undefined || f.step === null || !isFinite(f.step) ? DEFAULT_STEP_DEG : f.step;
  return `${f.name ? f.name + ': ' : ''}${fix}, ${what}, step ${fmt(step)}°` +
    (f.lock === 'auto' ? ', lock auto' : f.lock && f.lock.length ? `, lock ${f.lock.join(',')}` : '') +
    (f.from !== undefined && f.from !== null ? `, from ${fmt(f.from)}°` : '');
}

// State k (0-based) of a fold of n states, counted as the verdict counts them ("n states").
export function foldStateText(k, n, driveDeg) {
  const at = Number.isNaN(driveDeg) || driveDeg === null || driveDeg === undefined ? '' : `, drive ${fmt(driveDeg, 3)}°`;
  return `fold: state ${k + 1} of ${n}${at}`;
}

// The fold's verdict line: "valid: 19 states, <solver>" or the verdict with the states reached.
export function foldVerdictText(r) {
  const n = r.frames.length;
  if (r.valid) return `valid: ${n} state${n === 1 ? '' : 's'}${r.solver ? `, ${r.solver}` : ''}`;
  return n > 1 ? `${r.verdict}: ${n} states up to the stop` : `${r.verdict}`;
}
