// Assembly of the loop-closure Jacobian restricted to the free columns: dense column-major, or
// as a sparse least-squares object (Jᵀ in compressed columns) for CHOLMOD. Below rank.c and
// the solvers; above mechanism.c (loop evaluation) and sparse.c.
#include "kinematics_internal.h"

double *ori__kin_jacobian_dense(const ori_mechanism *m, const int *col_of_joint, int ncols, const double *th)
{
    size_t entries = (size_t)m->rows * (size_t)ncols;
    double *blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    ori__kin_eval(m, th, NULL, blocks, NULL);
    double *a = ori__calloc(entries + 1, sizeof(double));
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c) {
            int col = col_of_joint[m->loop_cols[L->col_first + c]];
            if (col < 0) continue;
            for (int r = 0; r < L->rows; ++r)
                a[(size_t)(L->row0 + r) + (size_t)m->rows * (size_t)col] = blocks[6 * (L->col_first + c) + r];
        }
    }
    ori__free(blocks);
    return a;
}

kin_sls *ori__kin_jacobian_sls(const ori_mechanism *m, const int *col_of_joint, int ncols, const double *th)
{
    return ori__kin_jacobian_sls_parts(m, col_of_joint, ncols, th, NULL, NULL, NULL);
}

kin_sls *ori__kin_jacobian_sls_parts(const ori_mechanism *m, const int *col_of_joint, int ncols, const double *th,
                                     int **colptr_out, int **rowind_out, double **vals_out)
{
    double *blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    ori__kin_eval(m, th, NULL, blocks, NULL);
    int *colptr = ori__alloc(sizeof(int) * ((size_t)m->rows + 1));
    int nnz = 0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        int k = 0;
        for (int c = 0; c < L->col_count; ++c) k += col_of_joint[m->loop_cols[L->col_first + c]] >= 0;
        nnz += k * L->rows;
    }
    int *rowind = ori__alloc(sizeof(int) * ((size_t)nnz + 1));
    double *vals = ori__alloc(sizeof(double) * ((size_t)nnz + 1));
    int *order = ori__alloc(sizeof(int) * ((size_t)m->entry_count + 1));
    int pos = 0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        int k = 0;
        for (int c = 0; c < L->col_count; ++c) {
            int fc = col_of_joint[m->loop_cols[L->col_first + c]];
            if (fc < 0) continue;
            int t = k++;
            while (t > 0 && col_of_joint[m->loop_cols[L->col_first + order[t - 1]]] > fc) {
                order[t] = order[t - 1];
                t--;
            }
            order[t] = c;
        }
        for (int r = 0; r < L->rows; ++r) {
            colptr[L->row0 + r] = pos;
            for (int t = 0; t < k; ++t) {
                rowind[pos] = col_of_joint[m->loop_cols[L->col_first + order[t]]];
                vals[pos] = blocks[6 * (L->col_first + order[t]) + r];
                pos++;
            }
        }
    }
    colptr[m->rows] = pos;
    kin_sls *s = ori__sls_create(ncols, m->rows, colptr, rowind);
    double *v = ori__sls_values(s);
    for (int k = 0; k < pos; ++k) v[k] = vals[k];
    ori__free(blocks);
    ori__free(order);
    if (colptr_out) {
        *colptr_out = colptr;
        *rowind_out = rowind;
        *vals_out = vals;
    } else {
        ori__free(colptr);
        ori__free(rowind);
        ori__free(vals);
    }
    return s;
}
