// libFuzzer target for the fold-sequence (SEQ.json) reader: parse, write back as JSON and
// parse that again, which must succeed and give the same folds. Errors always carry a
// position or a field. Any crash, leak or sanitizer report is a bug.
#include <orikin/sequence.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_sequence *s = NULL;
    ori_error err;
    if (ori_sequence_parse((const char *)data, size, &s, &err) != ORI_OK) {
        if (err.line < 1 && !err.field[0] && !err.message[0]) abort(); // errors say where
        return 0;
    }
    char *text = ori_sequence_to_json(s);
    ori_sequence *again = NULL;
    if (ori_sequence_parse(text, strlen(text), &again, &err) != ORI_OK) abort(); // our output must parse
    if (ori_sequence_fold_count(again) != ori_sequence_fold_count(s)) abort();
    for (int i = 0; i < ori_sequence_fold_count(s); ++i) {
        ori_sequence_fold a = ori_sequence_fold_at(s, i), b = ori_sequence_fold_at(again, i);
        if (a.driven_edge != b.driven_edge || a.fixed_face != b.fixed_face || a.locked_count != b.locked_count) abort();
    }
    ori_sequence_destroy(again);
    ori_buffer_free(text);
    ori_sequence_destroy(s);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
