// Small pieces the CLI and the studio both need: a path beside a file, face poses of a state.
#include "report.h"

#include <stdlib.h>
#include <string.h>

char *cli_path_beside(const char *file, const char *path)
{
    const char *slash = strrchr(file, '/');
    size_t dir = (path[0] == '/' || !slash) ? 0 : (size_t)(slash - file) + 1;
    char *p = malloc(dir + strlen(path) + 1);
    if (!p) abort(); // (the front ends' policy for small bookkeeping: out of memory ends the run)
    memcpy(p, file, dir);
    strcpy(p + dir, path);
    return p;
}

void cli_pose_faces(const ori_mechanism *mech, int fixed_face, const double *angles, const ori_v3 *positions,
                    ori_rigid *poses)
{
    ori_rigid g = ori_rigid_identity();
    ori_error err;
    if (ori_mechanism_face_pose_from_coords(mech, fixed_face, positions, &g, &err) != ORI_OK) g = ori_rigid_identity();
    ori_mechanism_face_poses(mech, angles, fixed_face, g, poses);
}

ori_rigid *cli_poses_from_positions(const ori_mechanism *mech, const ori_v3 *positions)
{
    if (!mech) return NULL;
    int nf = ori_mechanism_face_count(mech);
    ori_rigid *p = calloc((size_t)(nf ? nf : 1), sizeof *p);
    if (!p) abort();
    for (int f = 0; f < nf; ++f) {
        ori_error err;
        if (ori_mechanism_face_pose_from_coords(mech, f, positions, &p[f], &err) != ORI_OK) {
            free(p);
            return NULL;
        }
    }
    return p;
}
