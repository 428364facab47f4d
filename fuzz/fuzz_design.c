// libFuzzer target for the actuation design data of a FOLD file (edges_orikin:hinge,
// faces_orikin:panel, orikin:actuation, frame_unit): read it, write it back and read that again,
// which must succeed with the same hinges and panels. Errors name a field. Any crash, leak or
// sanitizer report is a bug.
#include <orikin/actuation.h>
#include <orikin/fold.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static ori_design *design_of(const ori_fold *doc, const ori_pattern *p, ori_error *err)
{
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    dd.pattern = p;
    dd.has_meters_per_unit = true; // the unit does not matter here; unitless files are fine
    dd.meters_per_unit = 1e-6;
    ori_design *d = NULL;
    return ori_design_create(&dd, &d, err) == ORI_OK ? d : NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_load_string((const char *)data, size, &doc, &err) != ORI_OK ||
        ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
        ori_fold_destroy(doc);
        return 0;
    }
    ori_design *d = design_of(doc, p, &err);
    if (!d) {
        if (!err.field[0] && !err.message[0]) abort(); // errors say where
    } else {
        if (ori_design_write(d, doc, &err) != ORI_OK) abort();
        ori_design *again = design_of(doc, p, &err);
        if (!again) abort(); // our output must read back
        for (int e = 0; e < ori_design_edge_count(d); ++e) {
            ori_hinge a, b;
            bool ha = ori_design_hinge(d, e, &a), hb = ori_design_hinge(again, e, &b);
            if (ha != hb || (ha && (a.width_m != b.width_m || a.thickness_m != b.thickness_m || a.has_wire != b.has_wire)))
                abort();
        }
        for (int f = 0; f < ori_design_face_count(d); ++f)
            if (ori_design_panel(d, f, NULL) != ori_design_panel(again, f, NULL)) abort();
        ori_design_destroy(again);
        ori_design_destroy(d);
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
