// The studio's API client: every request carries the session token; failures become ApiError
// with the server's one-line message; computations that run over a second show progress.

export class ApiError extends Error {
  constructor(status, message, body = null) {
    super(message);
    this.status = status;
    this.body = body; // the error's JSON ({error, conflict, …}) when there is one
  }
}

// A state in the binary form of /api/sequence/at and /api/fold/frame (little-endian float64):
// t, fold, drive_deg, residual, V, E, 0, 0, then 3V coordinates and E fold angles (degrees).
export function decodeState(buffer) {
  const d = new Float64Array(buffer);
  const V = d[4], E = d[5];
  return {
    t: d[0],
    fold: d[1],
    drive_deg: d[2],
    residual: d[3],
    positions: d.subarray(8, 8 + 3 * V),
    angles: d.subarray(8 + 3 * V, 8 + 3 * V + E),
  };
}

function query(params) {
  if (!params) return '';
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(params)) if (v !== undefined && v !== null) q.set(k, String(v));
  const s = q.toString();
  return s ? '?' + s : '';
}

export class Api {
  constructor(token, progress) {
    this.token = token;
    this.progress = progress; // {show(text), hide()}
    this.progressDelay = 1000; // show progress for anything over a second
    this.busy = 0;    // long computations running (progress shown)
    this.pending = 0; // requests in flight
  }

  async request(method, path, { params, body, type = 'application/json', as = 'json' } = {}) {
    const headers = { 'X-Orikin-Token': this.token };
    if (body !== undefined) headers['Content-Type'] = type;
    let res;
    this.pending++;
    try {
      res = await fetch('/api/' + path + query(params), {
        method,
        headers,
        body: body === undefined ? undefined : typeof body === 'string' ? body : JSON.stringify(body),
        cache: 'no-store',
      });
    } catch (e) {
      this.pending--;
      throw new ApiError(0, 'the studio server does not answer (was orikin view stopped?)');
    }
    try {
      return await this.read(res, as);
    } finally {
      this.pending--;
    }
  }

  async read(res, as) {
    if (!res.ok) {
      let message = res.statusText, body = null;
      try {
        body = await res.json();
        message = body.error || message;
      } catch (e) { /* not JSON */ }
      throw new ApiError(res.status, message, body);
    }
    if (as === 'response') return res;
    if (as === 'binary') return res.arrayBuffer();
    if (as === 'text') return res.text();
    return res.json();
  }

  get(path, params) { return this.request('GET', path, { params }); }
  post(path, body, params) { return this.request('POST', path, { params, body: body === undefined ? {} : body }); }
  text(path, params) { return this.request('GET', path, { params, as: 'text' }); }
  binary(path, params) { return this.request('GET', path, { params, as: 'binary' }); }
  postText(path, text, params) { return this.request('POST', path, { params, body: text, type: 'text/plain' }); }

  // Run a long request: after a second, show what runs and for how long (GET /api/progress).
  async compute(label, run) {
    this.busy++;
    let timer = null, stopped = false;
    const poll = async () => {
      if (stopped) return;
      try {
        const p = await this.get('progress');
        if (stopped) return;
        const what = p.busy ? `${p.job}: ${p.elapsed_s.toFixed(1)} s` : label;
        this.progress.show(p.fraction !== null ? `${what} (${Math.round(100 * p.fraction)} %)` : what + '…');
      } catch (e) { /* the next poll will tell */ }
      if (!stopped) timer = setTimeout(poll, 250);
    };
    timer = setTimeout(poll, this.progressDelay);
    try {
      return await run();
    } finally {
      stopped = true;
      clearTimeout(timer);
      this.busy--;
      if (this.busy === 0) this.progress.hide();
    }
  }
}
