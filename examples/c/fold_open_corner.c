// Fold the thesis' open corner with the library: load the crease pattern, build the
// substituted mechanism, fix the lower-left triangle, lock the down crease and turn the
// diagonal to 90 degrees; print the constrained angles and the end effector (thesis fig. 5-4).
//
//   cc fold_open_corner.c $(pkg-config --cflags --libs orikin) -o fold_open_corner
//   ./fold_open_corner examples/patterns/open-corner.fold
#include <orikin/orikin.h>
#include <stdio.h>

// The crease from (x0, y0) to (x1, y1), or -1.
static int crease(const ori_pattern *p, double x0, double y0, double x1, double y1)
{
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        if ((a.x == x0 && a.y == y0 && b.x == x1 && b.y == y1) || (a.x == x1 && a.y == y1 && b.x == x0 && b.y == y0))
            return e;
    }
    return -1;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "examples/patterns/open-corner.fold";
    ori_error err;
    char msg[512];
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    if (ori_fold_load_file(path, &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
        fprintf(stderr, "%s: %s\n", path, ori_error_format(&err, msg, sizeof msg));
        ori_fold_destroy(doc);
        return 3;
    }
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) {
        fprintf(stderr, "%s: %s\n", path, ori_error_format(&err, msg, sizeof msg));
        return 3;
    }
    int diag = crease(p, 1, 1, 0, 0), down = crease(p, 1, 1, 1, 0);
    int right = crease(p, 1, 1, 2, 1), up = crease(p, 1, 1, 1, 2), left = crease(p, 1, 1, 0, 1);
    // the fixed face: the one on the far side of the diagonal from the left crease
    ori_joint j = ori_mechanism_joint(m, ori_mechanism_edge_joint(m, down));
    int fixed = j.face_left;
    ori_joint jd = ori_mechanism_joint(m, ori_mechanism_edge_joint(m, diag));
    if (fixed != jd.face_left && fixed != jd.face_right) fixed = j.face_right;

    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = fixed;
    d.driven_edge = diag;
    d.to_rad = ORI_PI / 2;
    d.step_rad = ORI_PI / 2;
    d.locked_edges = &down;
    d.locked_count = 1;
    ori_motion *mo = NULL;
    if (ori_motion_solve(m, &d, &mo, &err) != ORI_OK) {
        fprintf(stderr, "%s: %s\n", path, ori_error_format(&err, msg, sizeof msg));
        return 3;
    }
    int last = ori_motion_frame_count(mo) - 1;
    printf("verdict: %s\n", ori_motion_verdict_name(ori_motion_verdict_of(mo)));
    if (last >= 0) {
        const double *a = ori_motion_frame_angles(mo, last);
        printf("diagonal %.9f, right %.9f, up %.9f, left %.9f degrees (residual %.1e)\n", ori_rad_to_deg(a[diag]),
               ori_rad_to_deg(a[right]), ori_rad_to_deg(a[up]), ori_rad_to_deg(a[left]), ori_motion_frame_residual(mo, last));
        ori_v3 ea, eb;
        if (ori_motion_frame_end_effector(mo, last, &ea, &eb))
            printf("end effector: (%.6f, %.6f, %.6f) in Frame A, (%.6f, %.6f, %.6f) in Frame B\n", ea.x, ea.y, ea.z, eb.x,
                   eb.y, eb.z);
    }
    int code = ori_motion_verdict_of(mo) == ORI_MOTION_VALID ? 0 : 1;
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return code;
}
