// The document as the page uses it: frame 0 of the FOLD text the server holds, with the face
// names and the face tree (orikin:faces_name, orikin:face_tree). Indices are FOLD indices.

export function parseDocument(fold) {
  const v = fold.vertices_coords || [];
  const ev = fold.edges_vertices || [];
  const asg = fold.edges_assignment || ev.map(() => 'U');
  const ang = fold.edges_foldAngle || ev.map(() => 0);
  const faces = fold.faces_vertices || [];
  const names = fold['orikin:faces_name'] || faces.map(() => null);
  const tree = fold['orikin:face_tree'] || [];
  const frames = (fold.file_frames || []).length + 1;
  const doc = {
    vertices: v.map((p) => [p[0], p[1], p.length > 2 ? p[2] : 0]),
    edges: ev,
    assignment: asg.map((a) => String(a).toUpperCase()),
    foldAngle: ang,
    faces,
    names,
    tree,
    frames,
    title: fold.file_title || '',
  };
  doc.flat = doc.vertices.map((p) => [p[0], p[1]]);
  doc.is3d = doc.vertices.some((p) => p[2] !== 0);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of doc.flat) {
    x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
  }
  if (!isFinite(x0)) { x0 = 0; y0 = 0; x1 = 1; y1 = 1; }
  doc.box = { x0, y0, x1, y1, size: Math.max(x1 - x0, y1 - y0) || 1 };
  // faces beside each edge, and each face's centroid (for labels and bones)
  doc.faceCentroid = faces.map((f) => centroid(f.map((i) => doc.flat[i])));
  return doc;
}

// Area centroid of a simple polygon (the vertex mean when degenerate).
export function centroid(pts) {
  let a = 0, cx = 0, cy = 0;
  for (let i = 0; i < pts.length; i++) {
    const [x0, y0] = pts[i], [x1, y1] = pts[(i + 1) % pts.length];
    const c = x0 * y1 - x1 * y0;
    a += c; cx += (x0 + x1) * c; cy += (y0 + y1) * c;
  }
  if (Math.abs(a) < 1e-300) {
    const n = pts.length || 1;
    return [pts.reduce((s, p) => s + p[0], 0) / n, pts.reduce((s, p) => s + p[1], 0) / n];
  }
  return [cx / (3 * a), cy / (3 * a)];
}

export const ASSIGNMENT_NAMES = { M: 'mountain', V: 'valley', B: 'boundary', F: 'flat', U: 'unassigned', C: 'cut', J: 'join' };

export function isCrease(a) {
  return a === 'M' || a === 'V' || a === 'U' || a === 'F';
}

// The face's label: its name, or "face N".
export function faceLabel(doc, f) {
  return doc.names[f] ? `${doc.names[f]} (face ${f})` : `face ${f}`;
}

export function fmt(x, digits = 6) {
  if (!isFinite(x)) return String(x);
  const s = x.toFixed(digits);
  return s.replace(/\.?0+$/, '') || '0';
}
