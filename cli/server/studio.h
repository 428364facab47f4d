// The studio's server (orikin view): a document held in memory, its JSON API as one handler
// function (studio_handle: no HTTP, called directly by tests and the fuzz target), and the HTTP
// front (libmicrohttpd: loopback, session token, Host check, embedded assets only).
//
// Functions: studio_default_def, studio_create, studio_unsaved, studio_recovery_pending,
// studio_destroy, studio_handle,
// studio_response_free, studio_body_limit, studio_version, studio_token_make,
// studio_http_start, studio_http_port, studio_http_stop, studio_assets_built,
// studio_asset_find.
//
// The API (docs/viewer.md) mirrors the CLI's --json outputs field for field. Every handler
// validates its input before touching the library (a bad index never reaches an assertion),
// works on a copy and publishes it only on success, so a failed request leaves the document
// exactly as it was.
#ifndef ORI_STUDIO_H
#define ORI_STUDIO_H

#include <stdbool.h>
#include <stddef.h>

// Largest JSON request body (bytes); POST /api/open takes files up to max_open_bytes.
#define STUDIO_MAX_BODY_BYTES ((size_t)4 << 20)
#define STUDIO_MAX_OPEN_BYTES ((size_t)64 << 20)
// Memory budget of the scrubbing cache of a sequence (bytes): exact states on a fine time grid.
#define STUDIO_CACHE_BYTES ((size_t)64 << 20)
// Finest grid of the scrubbing cache: states per fold (a multiple of 8, so that T = k/2, k/4 and
// k/8 are grid points).
#define STUDIO_GRID_MAX 720
// Bound on one computation (fold, sequence, restore): output frames × (vertices + edges + faces).
// At 4 ms per frame of a 100 × 100 Miura-ori (40,000 elements) this is about a second of work
// and at most a few hundred MB of recorded states; larger requests are refused up front.
#define STUDIO_WORK_LIMIT 1.2e7
// Most output frames of one fold.
#define STUDIO_MAX_FRAMES_PER_FOLD 3601
// Largest picture the studio draws (pixels or points: width × height), 4096 × 4096; a bigger
// one is `orikin render`'s job.
#define STUDIO_RENDER_MAX_PIXELS 16777216.0
// Largest animation (width × height × frames): 256 MB of frames at most.
#define STUDIO_ANIMATION_MAX_PIXELS 268435456.0
// Undo history depth (document states kept).
#define STUDIO_UNDO_DEPTH 100
// The session token: random bytes, written as hex.
#define STUDIO_TOKEN_BYTES 16
// Connections served at once, and the silence after which one is dropped: STUDIO_IDLE_SECONDS
// before it has shown the session token (a local user's idle connections free their slot
// soon), STUDIO_SESSION_IDLE_SECONDS once it has.
#define STUDIO_MAX_CONNECTIONS 1024
#define STUDIO_IDLE_SECONDS 10
#define STUDIO_SESSION_IDLE_SECONDS 300

typedef struct studio studio;

// Creation parameters; get them from studio_default_def().
typedef struct studio_def {
    const char *path;      // file given on the command line (.fold, .svg, .opx, .cp or SEQ .json); NULL = blank sheet
    double blank_side;     // side of the blank square sheet (> 0)
    size_t max_body_bytes; // JSON request bodies
    size_t max_open_bytes; // files opened through the page
    size_t cache_bytes;    // scrubbing cache budget (0 = no cache)
    double work_limit;     // bound on frames × elements of one computation
    double render_pixels;  // largest picture (width × height)
    double animation_pixels; // largest animation (width × height × frames)
    bool autosave;         // journal unsaved edits beside the file and offer earlier ones (default true)
} studio_def;

studio_def studio_default_def(void);

// Load def->path (or make the blank sheet) and, for a sequence, run it. Returns 0, or 3 (bad
// input: the message, one line naming the file and where, is written into err).
int studio_create(const studio_def *def, studio **out, char *err, size_t err_size);
// Whether the document has edits that are not on disk; journal gets the autosave that holds
// them ("" when there is none, e.g. a document dropped on the page).
bool studio_unsaved(studio *s, char *journal, size_t size);
// Whether an autosave of an earlier session waits for the page's recover or discard (journal: its path).
bool studio_recovery_pending(studio *s, char *journal, size_t size);
// Destroy a studio (NULL is a no-op). No request may be running.
void studio_destroy(studio *s);

// One query argument (percent-decoded).
typedef struct studio_arg {
    const char *key;
    const char *value;
} studio_arg;

// An API request, already past the HTTP checks (token, Host, body size).
typedef struct studio_request {
    const char *method;     // "GET", "POST"
    const char *path;       // "/api/fold"
    const studio_arg *args; // query arguments
    int arg_count;
    const char *body;       // request body (need not be NUL-terminated), may be NULL
    size_t body_size;
} studio_request;

// The answer: status, content type, body (malloc'd), and a file name for downloads.
typedef struct studio_response {
    int status;
    const char *content_type; // static string
    char *body;
    size_t size;
    char filename[160];       // Content-Disposition attachment name, "" when none
} studio_response;

// Answer an API request (method, path under /api/, arguments, body). Thread-safe: requests
// run concurrently; long computations run outside the document lock (one at a time, the
// others get 409 busy), so the page and GET /api/progress stay responsive.
void studio_handle(studio *s, const studio_request *req, studio_response *out);
// Free a response's body.
void studio_response_free(studio_response *r);
// Largest body accepted for a request path (bytes).
size_t studio_body_limit(const studio *s, const char *path);
// Document version: bumped by every change (tests check that failed requests leave it).
long studio_version(studio *s);

// A fresh session token (2 × STUDIO_TOKEN_BYTES hex digits + NUL) from the system's random
// source. Returns false when none is available.
bool studio_token_make(char *out, size_t size);

// --- HTTP --------------------------------------------------------------------------------

typedef struct studio_http studio_http;

// Serve s on host:port (host: a numeric address; NULL = 127.0.0.1; port 0 = any free port).
// Requests must name the server in their Host header (host or localhost, and the port) and
// API requests must carry the token (header X-Orikin-Token). Returns NULL with a message in
// err on failure.
studio_http *studio_http_start(studio *s, const char *host, int port, const char *token, char *err,
                               size_t err_size);
// The port the server listens on.
int studio_http_port(const studio_http *h);
// Stop serving (waits for running requests); NULL is a no-op.
void studio_http_stop(studio_http *h);

// --- embedded web assets ----------------------------------------------------------------

// One file of the web app, embedded at build time.
typedef struct studio_asset {
    const char *path;         // "/index.html", "/app.js", "/studio.css"
    const char *content_type;
    const unsigned char *data;
    size_t size;
} studio_asset;

// True when the web app was bundled into this binary (node_modules present at build time).
bool studio_assets_built(void);
// The asset served at path ("/" is /index.html), or NULL. Exact match against the embedded
// table: no request path ever reaches the file system.
const studio_asset *studio_asset_find(const char *path);

#endif
