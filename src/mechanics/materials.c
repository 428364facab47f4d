// The materials table: built-in values (data/materials.json compiled in, so that a fresh build
// needs no file at run time; test_actuation checks that the two agree) and JSON files that
// extend or replace them.
#include <jansson.h>
#include <stdlib.h>

#include "../core/json_internal.h"
#include "mechanics_internal.h"

// The same numbers as data/materials.json, written the same way (sources there and in
// docs/actuation.md). Absent properties are NaN here.
typedef struct builtin_material {
    const char *name;
    double e, yield, density, resistivity, jmax;
} builtin_material;

#define NA NAN
static const builtin_material builtin[] = {
    {"Au", 80e9, 206e6, 19300, 2.35e-8, 2e9},
    {"Ag", 83e9, 55e6, 10490, 1.59e-8, 1e10},
    {"Al", 69e9, 34e6, 2700, 2.65e-8, 1e10},
    {"Cr", 279e9, NA, 7190, 1.25e-7, NA},
    {"Cu", 110e9, 69e6, 8960, 1.68e-8, 1e10},
    {"Ni", 200e9, 148e6, 8908, 6.99e-8, NA},
    {"Ti", 116e9, 170e6, 4506, 4.2e-7, NA},
    {"Si", 169e9, NA, 2329, NA, NA},
    {"SiO2", 70e9, NA, 2200, NA, NA},
    {"Si3N4", 250e9, NA, 3100, NA, NA},
    {"SU-8", 2e9, NA, 1190, NA, NA},
    {"polyimide", 2.5e9, 69e6, 1420, NA, NA},
};
#undef NA

static ori_material from_builtin(const builtin_material *b)
{
    ori_material m;
    memset(&m, 0, sizeof m);
    ori__strlcpy(m.name, b->name, sizeof m.name);
    m.youngs_modulus_pa = b->e;
    m.density_kg_m3 = b->density;
    m.has_yield = !isnan(b->yield);
    m.yield_strength_pa = m.has_yield ? b->yield : 0.0;
    m.has_resistivity = !isnan(b->resistivity);
    m.resistivity_ohm_m = m.has_resistivity ? b->resistivity : 0.0;
    m.has_current_density_max = !isnan(b->jmax);
    m.current_density_max_a_m2 = m.has_current_density_max ? b->jmax : 0.0;
    return m;
}

static int find(const ori_materials *t, const char *name)
{
    for (int i = 0; i < t->count; ++i)
        if (strcmp(t->items[i].name, name) == 0) return i;
    return ORI_NULL_INDEX;
}

static void put(ori_materials *t, const ori_material *m)
{
    int i = find(t, m->name);
    if (i == ORI_NULL_INDEX) {
        ORI__PUSH(t->items, t->count, t->cap, *m);
    } else {
        t->items[i] = *m;
    }
}

ori_materials *ori_materials_create(void)
{
    ori_materials *t = ori__calloc(1, sizeof *t);
    for (size_t i = 0; i < sizeof builtin / sizeof builtin[0]; ++i) {
        ori_material m = from_builtin(&builtin[i]);
        put(t, &m);
    }
    return t;
}

void ori_materials_destroy(ori_materials *t)
{
    if (!t) return;
    ori__free(t->items);
    ori__free(t);
}

void ori__materials_copy(ori_materials *dst, const ori_materials *src)
{
    dst->count = 0;
    for (int i = 0; i < src->count; ++i) put(dst, &src->items[i]);
}

const ori_material *ori__materials_get(const ori_materials *t, const char *name)
{
    int i = find(t, name);
    return i == ORI_NULL_INDEX ? NULL : &t->items[i];
}

int ori_materials_count(const ori_materials *t)
{
    ORI_ASSERT(t);
    return t->count;
}

ori_material ori_materials_at(const ori_materials *t, int index)
{
    ORI_ASSERT(t && index >= 0 && index < t->count);
    return t->items[index];
}

int ori_materials_find(const ori_materials *t, const char *name)
{
    ORI_ASSERT(t && name);
    return find(t, name);
}

static bool positive(double x) { return isfinite(x) && x > 0.0; }

static ori_status validate(const ori_material *m, ori_error *error)
{
    if (m->name[0] == '\0' || !memchr(m->name, '\0', sizeof m->name))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "materials", ORI_NULL_INDEX,
                            "a material needs a name of 1 to %d bytes", ORI_MATERIAL_NAME_MAX - 1);
    const char *bad = !positive(m->youngs_modulus_pa)                                 ? "youngs_modulus_Pa"
                      : !positive(m->density_kg_m3)                                   ? "density_kg_m3"
                      : m->has_yield && !positive(m->yield_strength_pa)               ? "yield_strength_Pa"
                      : m->has_resistivity && !positive(m->resistivity_ohm_m)         ? "resistivity_ohm_m"
                      : m->has_current_density_max && !positive(m->current_density_max_a_m2) ? "current_density_max_A_m2"
                                                                                      : NULL;
    if (bad)
        return ori__fail_at(error, ORI_ERR_RANGE, "materials", ORI_NULL_INDEX, "%s: %s must be a positive number",
                            m->name, bad);
    return ORI_OK;
}

ori_status ori_materials_set(ori_materials *t, const ori_material *m, ori_error *error)
{
    ORI_ASSERT(t && m);
    ori_status st = validate(m, error);
    if (st != ORI_OK) return st;
    put(t, m);
    return ORI_OK;
}

static const char *const material_keys[] = {"youngs_modulus_Pa", "yield_strength_Pa", "density_kg_m3",
                                             "resistivity_ohm_m", "current_density_max_A_m2", "source"};

// One optional or required number of a material entry.
static ori_status read_number(json_t *obj, const char *name, const char *key, bool required, bool *has, double *out,
                              ori_error *error)
{
    json_t *v = json_object_get(obj, key);
    if (has) *has = false;
    if (!v || json_is_null(v)) {
        if (required)
            return ori__fail_at(error, ORI_ERR_TYPE, "materials", ORI_NULL_INDEX, "%s: missing \"%s\"", name, key);
        return ORI_OK;
    }
    if (!json_is_number(v))
        return ori__fail_at(error, ORI_ERR_TYPE, "materials", ORI_NULL_INDEX, "%s: \"%s\" must be a number", name, key);
    *out = json_number_value(v);
    if (has) *has = true;
    return ORI_OK;
}

static ori_status parse_material(const char *name, json_t *obj, ori_material *m, ori_error *error)
{
    memset(m, 0, sizeof *m);
    if (!json_is_object(obj))
        return ori__fail_at(error, ORI_ERR_TYPE, "materials", ORI_NULL_INDEX, "%s: must be an object", name);
    if (strlen(name) == 0 || strlen(name) >= sizeof m->name)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "materials", ORI_NULL_INDEX,
                            "material names have 1 to %d bytes", ORI_MATERIAL_NAME_MAX - 1);
    const char *key;
    json_t *v;
    json_object_foreach(obj, key, v)
    {
        bool known = false;
        for (size_t i = 0; i < sizeof material_keys / sizeof material_keys[0]; ++i) known |= strcmp(key, material_keys[i]) == 0;
        if (!known)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "materials", ORI_NULL_INDEX, "%s: unknown property \"%s\"", name,
                                key);
    }
    ori__strlcpy(m->name, name, sizeof m->name);
    ori_status st;
    if ((st = read_number(obj, name, "youngs_modulus_Pa", true, NULL, &m->youngs_modulus_pa, error)) != ORI_OK ||
        (st = read_number(obj, name, "density_kg_m3", true, NULL, &m->density_kg_m3, error)) != ORI_OK ||
        (st = read_number(obj, name, "yield_strength_Pa", false, &m->has_yield, &m->yield_strength_pa, error)) != ORI_OK ||
        (st = read_number(obj, name, "resistivity_ohm_m", false, &m->has_resistivity, &m->resistivity_ohm_m, error)) != ORI_OK ||
        (st = read_number(obj, name, "current_density_max_A_m2", false, &m->has_current_density_max,
                          &m->current_density_max_a_m2, error)) != ORI_OK)
        return st;
    json_t *src = json_object_get(obj, "source");
    if (src && !json_is_string(src))
        return ori__fail_at(error, ORI_ERR_TYPE, "materials", ORI_NULL_INDEX, "%s: \"source\" must be a string", name);
    return validate(m, error);
}

ori_status ori_materials_load(ori_materials *t, const char *json, size_t size, ori_error *error)
{
    ORI_ASSERT(t && json);
    json_t *root = ori__json_parse(json, size, JSON_REJECT_DUPLICATES, error);
    if (!root) return ORI_ERR_PARSE;
    ori_status st = ORI_OK;
    ori_materials next = {0};
    if (!json_is_object(root)) {
        st = ori__fail(error, ORI_ERR_TYPE, "a materials file is a JSON object {\"materials\": {…}}");
        goto done;
    }
    const char *key;
    json_t *v;
    json_object_foreach(root, key, v)
    {
        if (strcmp(key, "materials") != 0 && strcmp(key, "replace") != 0 && strcmp(key, "title") != 0 &&
            strcmp(key, "description") != 0) {
            st = ori__fail(error, ORI_ERR_ARGUMENT, "unknown key \"%s\" (expected materials, replace)", key);
            goto done;
        }
    }
    json_t *rep = json_object_get(root, "replace");
    if (rep && !json_is_boolean(rep)) {
        st = ori__fail_at(error, ORI_ERR_TYPE, "replace", ORI_NULL_INDEX, "must be true or false");
        goto done;
    }
    json_t *mats = json_object_get(root, "materials");
    if (!json_is_object(mats)) {
        st = ori__fail_at(error, ORI_ERR_TYPE, "materials", ORI_NULL_INDEX, "must be an object of materials by name");
        goto done;
    }
    if (!(rep && json_is_true(rep))) ori__materials_copy(&next, t);
    json_object_foreach(mats, key, v)
    {
        ori_material m;
        if ((st = parse_material(key, v, &m, error)) != ORI_OK) goto done;
        put(&next, &m);
    }
    // Adopt the merged table only when every entry was valid.
    ori__free(t->items);
    *t = next;
    next.items = NULL;
done:
    ori__free(next.items);
    json_decref(root);
    return st;
}

ori_status ori_materials_load_file(ori_materials *t, const char *path, ori_error *error)
{
    ORI_ASSERT(t && path);
    char *text = NULL;
    size_t size = 0;
    ori_status st = ori_file_read_all(path, (size_t)1 << 24, &text, &size, error);
    if (st != ORI_OK) return st;
    st = ori_materials_load(t, text, size, error);
    ori_buffer_free(text);
    return st;
}

char *ori_materials_to_json(const ori_materials *t)
{
    ORI_ASSERT(t);
    json_t *mats = json_object();
    for (int i = 0; i < t->count; ++i) {
        const ori_material *m = &t->items[i];
        json_t *o = json_object();
        json_object_set_new(o, "youngs_modulus_Pa", json_real(m->youngs_modulus_pa));
        if (m->has_yield) json_object_set_new(o, "yield_strength_Pa", json_real(m->yield_strength_pa));
        json_object_set_new(o, "density_kg_m3", json_real(m->density_kg_m3));
        if (m->has_resistivity) json_object_set_new(o, "resistivity_ohm_m", json_real(m->resistivity_ohm_m));
        if (m->has_current_density_max)
            json_object_set_new(o, "current_density_max_A_m2", json_real(m->current_density_max_a_m2));
        json_object_set_new(mats, m->name, o);
    }
    json_t *root = json_pack("{s:b,s:o}", "replace", 1, "materials", mats);
    char *text = json_dumps(root, JSON_COMPACT | JSON_REAL_PRECISION(17) | JSON_PRESERVE_ORDER);
    json_decref(root);
    char *out = ori__strdup(text ? text : "");
    free(text);
    return out;
}
