// The JSON of a layer count (orikin layers --count --json, orikin-layers-mpi --json): one
// builder, so that the serial and the distributed count print the same bytes by construction.
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>

#include "report.h"

// A count as a JSON integer when it fits int64, else as its decimal string.
static json_t *count_json(const char *decimal)
{
    bool digits = decimal && *decimal;
    for (const char *p = decimal; digits && *p; ++p) digits = *p >= '0' && *p <= '9';
    if (digits) {
        errno = 0;
        char *end;
        unsigned long long v = strtoull(decimal, &end, 10);
        if (!errno && !*end && v <= (unsigned long long)INT64_MAX) return json_integer((json_int_t)v);
    }
    return json_string(decimal ? decimal : "");
}

json_t *cli_layers_count_json(const ori_layers *L, bool budget_given, bool timeout_given)
{
    ori_layers_info info = ori_layers_get_info(L);
    ori_layers_conflict conf;
    bool unsat = ori_layers_get_conflict(L, &conf);
    json_t *o = json_object();
    char *states = ori_layers_state_count(L);
    json_object_set_new(o, "states", json_string(states));
    ori_buffer_free(states);
    json_t *comps = json_array();
    if (!unsat || conf.constraint == ORI_LAYERS_EXHAUSTED)
        for (int c = 0; c < ori_layers_component_count(L); ++c) {
            char *n = ori_layers_component_states(L, c);
            json_array_append_new(comps, count_json(n));
            ori_buffer_free(n);
        }
    json_object_set_new(o, "components", comps);
    json_object_set_new(o, "faces", json_integer(info.faces));
    json_object_set_new(o, "variables", json_integer(info.variables));
    json_t *cons = json_object();
    json_object_set_new(cons, "taco_taco", json_integer(info.taco_taco));
    json_object_set_new(cons, "taco_tortilla", json_integer(info.taco_tortilla));
    json_object_set_new(cons, "tortilla_tortilla", json_integer(info.tortilla_tortilla));
    json_object_set_new(cons, "transitivity", json_integer(info.transitivity));
    json_object_set_new(o, "constraints", cons);
    json_object_set_new(o, "tolerance", json_real(info.tolerance));
    json_object_set_new(o, "tolerance_source", json_string(info.tolerance_from_drawing ? "drawing" : "option"));
    json_t *noise = json_object();
    json_object_set_new(noise, "length", json_real(info.noise_length));
    json_object_set_new(noise, "angle", json_real(info.noise_angle));
    json_object_set_new(o, "drawing_noise", noise);
    if (unsat) {
        int nconf = ori_layers_conflict_faces(L, NULL, 0);
        int *conf_faces = malloc(sizeof(int) * (size_t)(nconf ? nconf : 1));
        ori_layers_conflict_faces(L, conf_faces, nconf);
        json_t *u = json_object();
        json_object_set_new(u, "constraint", json_string(ori_layers_constraint_name(conf.constraint)));
        json_t *fa = json_array();
        if (conf.face_count > 0)
            for (int i = 0; i < conf.face_count; ++i) json_array_append_new(fa, json_integer(conf.faces[i]));
        else
            for (int i = 0; i < nconf; ++i) json_array_append_new(fa, json_integer(conf_faces[i]));
        json_object_set_new(u, "faces", fa);
        json_t *inv = json_array();
        for (int i = 0; i < nconf; ++i) json_array_append_new(inv, json_integer(conf_faces[i]));
        json_object_set_new(u, "involved_faces", inv);
        if (conf.vertex != ORI_NULL_INDEX) json_object_set_new(u, "vertex", json_integer(conf.vertex));
        json_object_set_new(u, "detail", json_string(conf.detail));
        json_object_set_new(o, "unsatisfiable", u);
        free(conf_faces);
    } else {
        json_object_set_new(o, "unsatisfiable", json_null());
    }
    if (budget_given || timeout_given) json_object_set_new(o, "limited", json_boolean(info.limited));
    if (timeout_given) json_object_set_new(o, "timed_out", json_boolean(info.stopped));
    return o;
}
