// The Export menu and downloads: the document (FOLD, SVG, .cp, .opx), a picture or mesh of the
// state shown (the picture seen from the 3D view's camera, in its colours; the crease pattern
// when the flat sheet is shown), or the motion of the sequence or the fold ("format" or
// "format:of"). ctx: {state, $, api, v3, action, shownStateRef} (api and v3 read when used).
import { exportGroups, exportParams as buildExportParams, foldMotionExportable } from './requests.js';

export function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
}

export function createExport(ctx) {
  const { state, $ } = ctx;
  function params(format, of) {
    const f = state.session.export_formats.find((x) => x.format === format);
    const c = $('gl');
    return buildExportParams({
      format, kind: f ? f.kind : undefined, of, stateRef: of ? undefined : ctx.shownStateRef(),
      flat: state.shown === 'flat' && !state.doc.is3d, view: ctx.v3.viewAxes(),
      canvas: { width: c.clientWidth, height: c.clientHeight },
      colors: { front: $('color-front').value, back: $('color-back').value }, grid: ctx.v3.gridVisible !== false,
    });
  }
  async function exportAs(format, of) {
    await ctx.action(async () => {
      const p = params(format, of);
      const api = ctx.api;
      const run = () => api.request('GET', 'export', { params: p, as: 'response' });
      const res = p.format === 'fold' || p.format === 'svg' ? await run() : await api.compute('export', run);
      const cd = res.headers.get('Content-Disposition') || '';
      const m = /filename="([^"]+)"/.exec(cd);
      download(m ? m[1] : 'orikin.' + format, await res.blob());
    });
  }
  // One group per what is written; the motions only when there is one.
  function renderMenu() {
    const sel = $('export-format');
    if (!state.session) return;
    sel.querySelectorAll('optgroup').forEach((g) => g.remove());
    const groups = exportGroups(state.session.export_formats, {
      sequence: !!(state.sequence && state.sequence.frames && state.sequence.frames.length),
      fold: foldMotionExportable(state.fold),
      compliant: !!(state.compliant && state.compliant.load_steps > 0),
    });
    for (const { label, options } of groups) {
      const g = document.createElement('optgroup');
      g.label = label;
      for (const o of options) {
        const el = document.createElement('option');
        el.value = o.value;
        el.textContent = o.label;
        g.appendChild(el);
      }
      sel.appendChild(g);
    }
  }
  return { params, exportAs, renderMenu };
}
