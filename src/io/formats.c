// The one table of file formats: extension, kind and what orikin can do with it. Every
// *_from_path function (patterns and drawings, images, meshes) and ori_format_is_drawing read
// it; an extension is what follows the last '.' of the last path component, in any case.
#include <ctype.h>

#include "io_internal.h"

static const ori_format_info format_table[] = {
    {"fold", ORI_FORMAT_KIND_PATTERN, ORI_FORMAT_FOLD, true, true},
    {"svg", ORI_FORMAT_KIND_DRAWING, ORI_FORMAT_SVG, true, true},
    {"opx", ORI_FORMAT_KIND_DRAWING, ORI_FORMAT_OPX, true, true},
    {"cp", ORI_FORMAT_KIND_DRAWING, ORI_FORMAT_CP, true, true},
    {"svg", ORI_FORMAT_KIND_IMAGE, ORI_IMAGE_SVG, false, true},
    {"pdf", ORI_FORMAT_KIND_IMAGE, ORI_IMAGE_PDF, false, true},
    {"png", ORI_FORMAT_KIND_IMAGE, ORI_IMAGE_PNG, false, true},
    {"obj", ORI_FORMAT_KIND_MESH, ORI_MESH_OBJ, false, true},
    {"stl", ORI_FORMAT_KIND_MESH, ORI_MESH_STL, false, true},
    {"ply", ORI_FORMAT_KIND_MESH, ORI_MESH_PLY, false, true},
    {"gltf", ORI_FORMAT_KIND_MESH, ORI_MESH_GLTF, false, true},
    {"glb", ORI_FORMAT_KIND_MESH, ORI_MESH_GLB, false, true},
};
enum { FORMAT_COUNT = (int)(sizeof format_table / sizeof format_table[0]) };

const ori_format_info *ori_format_table(int *count)
{
    if (count) *count = FORMAT_COUNT;
    return format_table;
}

// The lower-case extension of path into ext (capacity 8); false when it has none or a longer one.
static bool extension_of(const char *path, char ext[8])
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash)) return false;
    size_t n = strlen(dot + 1);
    if (n == 0 || n >= 8) return false;
    for (size_t i = 0; i < n; ++i) ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    ext[n] = '\0';
    return true;
}

const ori_format_info *ori_format_find(const char *path, ori_format_kind kind)
{
    char ext[8];
    if (!path || !extension_of(path, ext)) return NULL;
    for (int i = 0; i < FORMAT_COUNT; ++i) {
        const ori_format_info *f = &format_table[i];
        bool kind_ok = kind == ORI_FORMAT_KIND_ANY || f->kind == kind ||
                       (kind == ORI_FORMAT_KIND_DOCUMENT &&
                        (f->kind == ORI_FORMAT_KIND_PATTERN || f->kind == ORI_FORMAT_KIND_DRAWING));
        if (kind_ok && strcmp(ext, f->extension) == 0) return f;
    }
    return NULL;
}

const char *ori__format_name(ori_format_kind kind, int code)
{
    for (int i = 0; i < FORMAT_COUNT; ++i)
        if (format_table[i].kind == kind && format_table[i].code == code) return format_table[i].extension;
    return "unknown";
}

ori_format ori_format_from_path(const char *path)
{
    ORI_ASSERT(path);
    const ori_format_info *f = ori_format_find(path, ORI_FORMAT_KIND_DOCUMENT);
    return f ? (ori_format)f->code : ORI_FORMAT_UNKNOWN;
}

const char *ori_format_name(ori_format format)
{
    const char *s = ori__format_name(ORI_FORMAT_KIND_PATTERN, (int)format);
    return strcmp(s, "unknown") != 0 ? s : ori__format_name(ORI_FORMAT_KIND_DRAWING, (int)format);
}

bool ori_format_is_drawing(ori_format format)
{
    return strcmp(ori__format_name(ORI_FORMAT_KIND_DRAWING, (int)format), "unknown") != 0;
}
