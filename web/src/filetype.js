// What a file opened or dropped on the page is, from its name first (a browser types .svg as
// image/svg+xml, yet an SVG is a crease pattern here) and its MIME type only when the name says
// nothing. Pure.

const PATTERN_EXTENSIONS = ['.fold', '.svg', '.opx', '.cp'];
const IMAGE_EXTENSIONS = ['.png', '.jpg', '.jpeg', '.gif', '.webp', '.bmp', '.avif'];

export function extensionOf(name) {
  const m = /\.[^./\\]+$/.exec(String(name || '').toLowerCase());
  return m ? m[0] : '';
}

// 'pattern' (FOLD, SVG, OPX, CP: POST /api/open), 'json' (a SEQ.json or a composite), 'image'
// (a raster image: a texture, only through the texture action), or 'unknown'.
export function fileKind(name, type = '') {
  const ext = extensionOf(name);
  if (PATTERN_EXTENSIONS.includes(ext)) return 'pattern';
  if (ext === '.json') return 'json';
  if (IMAGE_EXTENSIONS.includes(ext)) return 'image';
  if (ext === '') {
    const t = String(type || '').toLowerCase();
    if (t === 'image/svg+xml') return 'pattern';
    if (t.startsWith('image/')) return 'image';
    if (t === 'application/json') return 'json';
  }
  return 'unknown';
}

// What a JSON file holds: 'sequence' (has "folds"), 'composite' (has "creases"), or null.
export function jsonKind(j) {
  if (j && Array.isArray(j.folds)) return 'sequence';
  if (j && Array.isArray(j.creases)) return 'composite';
  return null;
}
