// libFuzzer target for the materials-table reader (--materials FILE): merge into the built-in
// table, write the table back as JSON and read that again, which must succeed and give the same
// materials. A failed load leaves the table unchanged. Any crash, leak or sanitizer report is a bug.
#include <orikin/actuation.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_materials *t = ori_materials_create();
    int before = ori_materials_count(t);
    ori_error err;
    if (ori_materials_load(t, (const char *)data, size, &err) != ORI_OK) {
        if (ori_materials_count(t) != before) abort(); // nothing partial
        if (!err.message[0]) abort();                   // errors say why
        ori_materials_destroy(t);
        if (ori_alloc_live_count() != 0) abort();
        return 0;
    }
    char *text = ori_materials_to_json(t);
    ori_materials *again = ori_materials_create();
    if (ori_materials_load(again, text, strlen(text), &err) != ORI_OK) abort(); // our output must read back
    if (ori_materials_count(again) != ori_materials_count(t)) abort();
    for (int i = 0; i < ori_materials_count(t); ++i) {
        ori_material a = ori_materials_at(t, i);
        int j = ori_materials_find(again, a.name);
        if (j < 0) abort();
        ori_material b = ori_materials_at(again, j);
        if (a.youngs_modulus_pa != b.youngs_modulus_pa || a.density_kg_m3 != b.density_kg_m3 || a.has_yield != b.has_yield)
            abort();
    }
    ori_materials_destroy(again);
    ori_buffer_free(text);
    ori_materials_destroy(t);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
