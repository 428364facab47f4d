// Opening files: by the Open… dialog or a drop, a crease pattern (FOLD, SVG, OPX, CP: typed by
// its name, filetype.js), a fold sequence or a composite (.json); an image only through the
// texture action. ctx: {state, $, api, v3, action, message, clearErrors, runSequence,
// renderCollection, forgetDocument, refresh, setupTimeline}.
import { fileKind, jsonKind } from './filetype.js';

export function createFiles(ctx) {
  const { state, $, message } = ctx;
  async function openNow(file) {
    const name = file.name;
    const kind = fileKind(name, file.type);
    if (kind === 'image') {
      message(`${name} is an image: use texture… (in the 3D view's tools) to map it on the paper`, true);
      return;
    }
    const text = await file.text();
    if (kind === 'json') {
      let j;
      try { j = JSON.parse(text); } catch (e) { message(`${name}: malformed JSON: ${e.message}`, true); return; }
      if (jsonKind(j) === 'sequence') {
        ctx.clearErrors();
        await ctx.action(() => ctx.runSequence(j.folds, 'sequence'));
        return;
      }
      if (jsonKind(j) === 'composite') {
        const label = j.name || name.replace(/\.json$/i, '');
        state.composites.push({ name: label, pattern: j });
        ctx.renderCollection();
        message(`composite ${label} added to the collection`);
        return;
      }
      message(`${name}: a JSON file here is a fold sequence ("folds") or a composite ("creases")`, true);
      return;
    }
    await ctx.action(async () => {
      await ctx.api.compute('opening ' + name, () => ctx.api.postText('open', text, { name }));
      ctx.forgetDocument();
      message(`opened ${name}`);
      await ctx.refresh();
      ctx.setupTimeline();
      ctx.v3.fit();
    });
  }
  return {
    async open(file) {
      state.work++; // reading the file takes a moment before any request: count it as busy
      try {
        await openNow(file);
      } finally {
        state.work--;
      }
    },
    // The texture action: an image on the front side of the paper.
    async openTexture(file) {
      const url = URL.createObjectURL(file);
      await ctx.action(async () => {
        await ctx.v3.setTexture(url);
        $('texture-clear').hidden = false;
        message(`texture: ${file.name} on the front side`);
      });
    },
  };
}
