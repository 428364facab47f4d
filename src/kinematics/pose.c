// Posing a state: the world geometry of the sheet for fold angles read from a file or computed.
// Rounded angles (a FOLD frame's edges_foldAngle) are first closed exactly by a minimum-norm
// Gauss–Newton projection onto the loop-closure manifold, as the fold solver does for its start.
#include "kinematics_internal.h"

ori_status ori_mechanism_pose_state(const ori_mechanism *m, const double *angles_rad, int fixed_face,
                                    ori_rigid fixed_pose, double *closed_angles_rad, ori_v3 *positions,
                                    ori_rigid *poses, ori_error *error)
{
    ORI_ASSERT(m && angles_rad);
    if (fixed_face < 0 || fixed_face >= m->face_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", fixed_face, "no face %d (the sheet has %d)",
                            fixed_face, m->face_count);
    int J = m->joint_count;
    for (int e = 0; e < m->edge_count; ++e)
        if (!isfinite(angles_rad[e]) || fabs(angles_rad[e]) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD)
            return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "fold angle outside [-180°, 180°]");
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *edge_th = ori__alloc(sizeof(double) * (size_t)(m->edge_count + 1));
    ori__kin_edges_to_joints(m, angles_rad, th);
    ori_status st = ORI_OK;
    double r0 = ori__kin_residual(m, th);
    if (!(r0 <= ORI_TOL_START_RESIDUAL)) {
        st = ori__fail(error, ORI_ERR_ARGUMENT,
                       "the fold angles do not close the loops (residual %.3g above %.0e): not a state of this sheet",
                       r0, ORI_TOL_START_RESIDUAL);
        goto done;
    }
    if (r0 > ORI_TOL_RESIDUAL) {
        int *col = ori__alloc(sizeof(int) * (size_t)(J + 1));
        int n = 0;
        for (int j = 0; j < J; ++j) col[j] = m->joints[j].kind == ORI_JOINT_REVOLUTE ? n++ : KIN_FIXED;
        kin_solver_opts opts = {ORI_LINEAR_AUTO, true};
        kin_solver *s = ori__kin_solver_create(m, col, n, ORI_NULL_INDEX, &opts);
        int its;
        double res;
        bool ok = ori__kin_correct(s, th, ORI_KIN_NEWTON_MAX, &its, &res);
        ori__kin_solver_destroy(s);
        ori__free(col);
        if (!ok) {
            st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the fold angles could not be closed exactly (residual %.3g)", res);
            goto done;
        }
    }
    ori__kin_joints_to_edges(m, th, edge_th);
    if (closed_angles_rad)
        for (int e = 0; e < m->edge_count; ++e) closed_angles_rad[e] = edge_th[e];
    if (positions) ori_mechanism_vertex_positions(m, edge_th, fixed_face, fixed_pose, positions);
    if (poses) ori_mechanism_face_poses(m, edge_th, fixed_face, fixed_pose, poses);
done:
    ori__free(th);
    ori__free(edge_th);
    return st;
}
