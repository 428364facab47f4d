// Rows of the "Bounded work" table in docs/conventions.md that no other test reaches: each bound
// hit exactly (the last value allowed runs, the next one is refused with the bound named).
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "studio.h"
#include "support.h"

TestSuite(bounds, .init = test_leak_setup, .fini = test_leak_check);

static int fold_request(studio *s, double step_deg, char *body_out, size_t size)
{
    char body[256];
    snprintf(body, sizeof body, "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": 90, \"step\": %.17g}", step_deg);
    studio_request req = {"POST", "/api/fold", NULL, 0, body, strlen(body)};
    studio_response r;
    studio_handle(s, &req, &r);
    snprintf(body_out, size, "%.*s", (int)r.size, r.body);
    int status = r.status;
    studio_response_free(&r);
    return status;
}

// The studio's fold: 3,601 states per fold. 90° at 0.025° is 3,601 states (the start and 3,600
// steps): answered, every state there; a step a little finer is refused (400) naming the bound,
// and the document is unchanged.
Test(bounds, studio_fold_states_per_fold)
{
    cr_assert_eq(chdir(ORI_SOURCE_DIR), 0);
    studio_def d = studio_default_def();
    d.path = "examples/patterns/open-corner.fold";
    d.cache_bytes = 0;
    studio *s = NULL;
    char err[512];
    cr_assert_eq(studio_create(&d, &s, err, sizeof err), 0, "%s", err);
    cr_assert_eq(STUDIO_MAX_FRAMES_PER_FOLD, 3601);
    char *body = malloc(1 << 24);
    int st = fold_request(s, 90.0 / 3600.0, body, 1 << 24);
    cr_assert_eq(st, 200, "%.300s", body);
    json_t *j = json_loads(body, 0, NULL);
    cr_assert(j);
    cr_assert_eq(json_array_size(json_object_get(j, "frames")), 3601);
    json_decref(j);
    long version = studio_version(s);
    st = fold_request(s, 90.0 / 3610.0, body, 1 << 24);
    cr_assert_eq(st, 400, "%.300s", body);
    cr_assert(strstr(body, "3611 states") && strstr(body, "limit is 3601 states"), "%s", body);
    cr_assert_eq(studio_version(s), version);
    free(body);
    studio_destroy(s);
}
