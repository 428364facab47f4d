// Bodies and parameters of the page's API requests, built from the user's choices. Pure: the
// caller reads the inputs and passes their values.

// POST /api/fold from the fold panel. spec: {fix, drive, locks (Set or array), lockAuto,
// symmetric, drives: [E…]}; inputs: {to, step, from ('' = the current state), frame}. A fix
// of -1 is left out (the server uses the CLI's default face); so is the drive when the fold
// goes toward the targets ({percent}).
export function foldBody(spec, inputs) {
  const body = {};
  if (spec.fix >= 0) body.fix = spec.fix;
  const drives = spec.drives && spec.drives.length ? spec.drives : spec.drive >= 0 ? [spec.drive] : [];
  if (inputs.percent !== undefined && inputs.percent !== null) {
    body.percent = +inputs.percent;
  } else {
    if (!drives.length) throw new Error('compute: choose the driven crease (folding properties: drive), or fold with the slider');
    body.drive = drives.length === 1 ? drives[0] : [...drives];
    // several drives: one target each ("90,45"), or one for all
    const to = String(inputs.to ?? '').split(',').map((x) => x.trim()).filter((x) => x !== '').map(Number);
    if (drives.length === 1) body.to = to.length ? to[0] : NaN;
    else if (to.length === 1 || to.length === drives.length) body.to = drives.map((_, i) => to[to.length === 1 ? 0 : i]);
    else throw new Error(`compute: ${drives.length} drives take ${drives.length} target angles ("to": a,b,…) or one for all`);
  }
  if (inputs.step !== undefined && inputs.step !== '' && isFinite(+inputs.step)) body.step = +inputs.step;
  if (spec.lockAuto) body.lock = 'auto';
  else body.lock = [...(spec.locks || [])].sort((a, b) => a - b);
  if (spec.symmetric) body.symmetric = true;
  const from = String(inputs.from ?? '').trim();
  if (from !== '' && body.percent === undefined) body.from = +from;
  if (inputs.frame > 0) body.frame = +inputs.frame;
  return body;
}

// The fold of the folding manager built from a fold request.
export function sequenceFold(body, name) {
  const f = { name };
  for (const k of ['fix', 'drive', 'to', 'percent', 'step', 'lock', 'from', 'symmetric']) if (body[k] !== undefined) f[k] = body[k];
  return f;
}

export function sequenceJson(pattern, folds) {
  return { pattern, folds };
}

// Whether a computed fold (its POST /api/fold answer) can be exported as a motion, as the server
// and `orikin export --animate` take it: a single-drive fold when valid; a fold mode (toward the
// targets, several drives, symmetric) when it reached its goal or recorded a partial motion, never
// against its assignment.
export function foldMotionExportable(fold) {
  if (!fold || !Array.isArray(fold.frames) || !fold.frames.length) return false;
  if (!fold.mode) return fold.valid === true;
  return fold.verdict !== 'invalid assignment' && (fold.verdict === 'reached' || fold.frames.length >= 2);
}

// The export menu's groups: [{label, options: [{value, label}]}]. Each format once for the
// document, the pictures and the meshes; the motions only when there is one (the sequence's,
// the fold's), so that a plain document lists glTF once.
export function exportGroups(formats, { sequence = false, fold = false, compliant = false } = {}) {
  const groups = [
    ['crease pattern', (f) => f.kind === 'document', null, true],
    ['picture of the state shown', (f) => f.kind === 'picture', null, true],
    ['mesh of the state shown', (f) => f.kind === 'mesh', null, true],
    ['motion of the sequence', (f) => f.motion, 'sequence', sequence],
    ['motion of the fold', (f) => f.motion, 'fold', fold],
    // (its faces bend: a glTF morphs through its states)
    ['motion of the compliant fold', (f) => f.motion, 'compliant', compliant],
  ];
  const out = [];
  for (const [label, take, of, shown] of groups) {
    if (!shown) continue;
    const options = formats.filter(take).map((f) => ({
      value: of ? `${f.format}:${of}` : f.format,
      label: of ? f.label.replace(/ mesh$/, ' animation') : f.label,
    }));
    if (options.length) out.push({ label, options });
  }
  return out;
}

// GET /api/export's parameters. kind: the format's kind; of: 'sequence'/'fold' or undefined (the
// state shown, stateRef); view: {eye, up} of the 3D camera; canvas: {width, height} of the 3D
// view (CSS pixels); flat: the flat sheet is shown; colors {front, back}; grid.
export function exportParams({ format, kind, of, stateRef, flat, view, canvas, colors, grid }) {
  const params = { format };
  if (!kind || kind === 'document') return params;
  if (of) params.of = of;
  else Object.assign(params, stateRef);
  // a compliant fold is shown coloured by strain: so are its pictures and its motion
  if ((kind === 'picture' && !flat && params.compliant) || (kind === 'animation' && of === 'compliant')) params.color = 'strain';
  if ((kind === 'picture' && !flat) || kind === 'animation') {
    params.eye = view.eye.map((x) => +x.toPrecision(12)).join(',');
    params.up = view.up.map((x) => +x.toPrecision(12)).join(',');
    params.perspective = 1;
    params.front = colors.front;
    params.back = colors.back;
    if (grid) params.grid = 1;
    const w = Math.max(1, Math.round(2 * canvas.width)), h = Math.max(1, Math.round(2 * canvas.height));
    const k = Math.min(1, 4096 / w, 4096 / h, kind === 'animation' ? 800 / w : 1);
    params.size = `${Math.max(1, Math.round(w * k))}x${Math.max(1, Math.round(h * k))}`;
  } else if (kind === 'mesh') {
    params.front = colors.front;
    params.back = colors.back;
  }
  return params;
}
