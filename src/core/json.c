// JSON parsing with the library's error reporting (json_internal.h).
#include "json_internal.h"

json_t *ori__json_parse(const char *text, size_t size, size_t flags, ori_error *error)
{
    // A UTF-8 byte-order mark (some Windows editors write one) is not part of the JSON text.
    if (size >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) text += 3, size -= 3;
    json_error_t je;
    json_t *root = json_loadb(text, size, flags, &je);
    if (!root)
        ori__fail_pos(error, ORI_ERR_PARSE, je.line > 0 ? je.line : 1, je.column > 0 ? je.column : 1, "%s", je.text);
    return root;
}
