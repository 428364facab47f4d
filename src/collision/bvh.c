// Broad phase: a bounding-volume hierarchy of axis-aligned face boxes, built by median splits
// along the longest axis of the box centres (O(n log n)), traversed against itself for the pairs
// of nearby boxes and by branch and bound for the nearest pair. Both traversals use an explicit
// stack, so their cost is proportional to the pairs they report, not to n².
#include "collision_internal.h"

#define LEAF_ITEMS 4

void col_bvh_free(col_bvh *bvh)
{
    ori__free(bvh->nodes);
    ori__free(bvh->items);
    ori__free(bvh->keys);
    ori__free(bvh->stack);
    memset(bvh, 0, sizeof *bvh);
}

static double centre(const col_box *b, int axis)
{
    return axis == 0 ? b->lo.x + b->hi.x : axis == 1 ? b->lo.y + b->hi.y : b->lo.z + b->hi.z;
}

// Partition items[lo..hi) so that the k-th smallest key is at k (quickselect); keys[item] is
// the item's box centre along the split axis.
static void select_kth(int *items, int lo, int hi, int k, const double *keys)
{
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        // median of three as pivot
        double a = keys[items[lo]], b = keys[items[mid]], cc = keys[items[hi - 1]];
        double pivot = a < b ? (b < cc ? b : (a < cc ? cc : a)) : (a < cc ? a : (b < cc ? cc : b));
        int i = lo, j = hi - 1;
        while (i <= j) {
            while (keys[items[i]] < pivot) i++;
            while (keys[items[j]] > pivot) j--;
            if (i <= j) {
                int t = items[i];
                items[i] = items[j];
                items[j] = t;
                i++;
                j--;
            }
        }
        if (k <= j) hi = j + 1;
        else if (k >= i) lo = i;
        else return;
    }
}

static int new_node(col_bvh *bvh)
{
    ORI__RESERVE(bvh->nodes, bvh->node_cap, bvh->node_count + 1);
    return bvh->node_count++;
}

static int build(col_bvh *bvh, int first, int count)
{
    int id = new_node(bvh);
    col_box box = bvh->boxes[bvh->items[first]];
    ori_v3 clo = ori_v3_make(INFINITY, INFINITY, INFINITY), chi = ori_v3_make(-INFINITY, -INFINITY, -INFINITY);
    for (int i = first; i < first + count; ++i) {
        const col_box *b = &bvh->boxes[bvh->items[i]];
        box.lo.x = b->lo.x < box.lo.x ? b->lo.x : box.lo.x;
        box.lo.y = b->lo.y < box.lo.y ? b->lo.y : box.lo.y;
        box.lo.z = b->lo.z < box.lo.z ? b->lo.z : box.lo.z;
        box.hi.x = b->hi.x > box.hi.x ? b->hi.x : box.hi.x;
        box.hi.y = b->hi.y > box.hi.y ? b->hi.y : box.hi.y;
        box.hi.z = b->hi.z > box.hi.z ? b->hi.z : box.hi.z;
        double cx = centre(b, 0), cy = centre(b, 1), cz = centre(b, 2);
        clo.x = cx < clo.x ? cx : clo.x;
        clo.y = cy < clo.y ? cy : clo.y;
        clo.z = cz < clo.z ? cz : clo.z;
        chi.x = cx > chi.x ? cx : chi.x;
        chi.y = cy > chi.y ? cy : chi.y;
        chi.z = cz > chi.z ? cz : chi.z;
    }
    bvh->nodes[id].box = box;
    if (count <= LEAF_ITEMS) {
        bvh->nodes[id].left = bvh->nodes[id].right = -1;
        bvh->nodes[id].first = first;
        bvh->nodes[id].count = count;
        return id;
    }
    double ex = chi.x - clo.x, ey = chi.y - clo.y, ez = chi.z - clo.z;
    int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
    int half = count / 2;
    double *keys = bvh->keys;
    for (int i = first; i < first + count; ++i) keys[bvh->items[i]] = centre(&bvh->boxes[bvh->items[i]], axis);
    select_kth(bvh->items, first, first + count, first + half, keys);
    int l = build(bvh, first, half);
    int r = build(bvh, first + half, count - half);
    bvh->nodes[id].left = l;
    bvh->nodes[id].right = r;
    bvh->nodes[id].first = first;
    bvh->nodes[id].count = count;
    return id;
}

void col_bvh_build(col_bvh *bvh, const col_box *boxes, int n)
{
    bvh->boxes = boxes;
    bvh->node_count = 0;
    if (n <= 0) return;
    ORI__RESERVE(bvh->items, bvh->item_cap, n);
    ORI__RESERVE(bvh->keys, bvh->key_cap, n);
    ORI__RESERVE(bvh->nodes, bvh->node_cap, 2 * (n / LEAF_ITEMS + 1) + 1);
    for (int i = 0; i < n; ++i) bvh->items[i] = i;
    build(bvh, 0, n);
}

static bool is_leaf(const col_node *n) { return n->left < 0; }

void col_bvh_refit(col_bvh *bvh, const col_box *boxes)
{
    bvh->boxes = boxes;
    // children come after their parent (build numbers the nodes in pre-order)
    for (int id = bvh->node_count - 1; id >= 0; --id) {
        col_node *nd = &bvh->nodes[id];
        col_box box;
        if (is_leaf(nd)) {
            box = boxes[bvh->items[nd->first]];
            for (int i = nd->first + 1; i < nd->first + nd->count; ++i) {
                const col_box *b = &boxes[bvh->items[i]];
                box.lo = ori_v3_make(fmin(box.lo.x, b->lo.x), fmin(box.lo.y, b->lo.y), fmin(box.lo.z, b->lo.z));
                box.hi = ori_v3_make(fmax(box.hi.x, b->hi.x), fmax(box.hi.y, b->hi.y), fmax(box.hi.z, b->hi.z));
            }
        } else {
            const col_box *l = &bvh->nodes[nd->left].box, *r = &bvh->nodes[nd->right].box;
            box.lo = ori_v3_make(fmin(l->lo.x, r->lo.x), fmin(l->lo.y, r->lo.y), fmin(l->lo.z, r->lo.z));
            box.hi = ori_v3_make(fmax(l->hi.x, r->hi.x), fmax(l->hi.y, r->hi.y), fmax(l->hi.z, r->hi.z));
        }
        nd->box = box;
    }
}

static void push2(col_bvh *bvh, int *top, int a, int b)
{
    ORI__RESERVE(bvh->stack, bvh->stack_cap, *top + 2);
    bvh->stack[(*top)++] = a;
    bvh->stack[(*top)++] = b;
}

void col_bvh_self_pairs(col_bvh *bvh, double margin, col_pair_fn *fn, void *user)
{
    if (bvh->node_count == 0) return;
    int top = 0;
    push2(bvh, &top, 0, 0);
    while (top > 0) {
        int b = bvh->stack[--top], a = bvh->stack[--top];
        const col_node *na = &bvh->nodes[a], *nb = &bvh->nodes[b];
        if (a == b) {
            if (is_leaf(na)) {
                for (int i = na->first; i < na->first + na->count; ++i)
                    for (int j = i + 1; j < na->first + na->count; ++j) {
                        int x = bvh->items[i], y = bvh->items[j];
                        if (!col_box_near(&bvh->boxes[x], &bvh->boxes[y], margin)) continue;
                        if (!fn(user, x < y ? x : y, x < y ? y : x)) return;
                    }
            } else {
                push2(bvh, &top, na->left, na->left);
                push2(bvh, &top, na->right, na->right);
                push2(bvh, &top, na->left, na->right);
            }
            continue;
        }
        if (!col_box_near(&na->box, &nb->box, margin)) continue;
        if (is_leaf(na) && is_leaf(nb)) {
            for (int i = na->first; i < na->first + na->count; ++i)
                for (int j = nb->first; j < nb->first + nb->count; ++j) {
                    int x = bvh->items[i], y = bvh->items[j];
                    if (!col_box_near(&bvh->boxes[x], &bvh->boxes[y], margin)) continue;
                    if (!fn(user, x < y ? x : y, x < y ? y : x)) return;
                }
        } else if (is_leaf(nb) || (!is_leaf(na) && na->count >= nb->count)) {
            // descend the inner node holding more items
            push2(bvh, &top, na->left, b);
            push2(bvh, &top, na->right, b);
        } else {
            push2(bvh, &top, a, nb->left);
            push2(bvh, &top, a, nb->right);
        }
    }
}

typedef struct nearest_ctx {
    col_bvh *bvh;
    col_dist_fn *fn;
    void *user;
    double best;
} nearest_ctx;

static void nearest_rec(nearest_ctx *x, int a, int b)
{
    const col_node *na = &x->bvh->nodes[a], *nb = &x->bvh->nodes[b];
    if (a != b && col_box_dist2(&na->box, &nb->box) >= x->best * x->best) return;
    if (is_leaf(na) && is_leaf(nb)) {
        for (int i = na->first; i < na->first + na->count; ++i)
            for (int j = (a == b ? i + 1 : nb->first); j < nb->first + nb->count; ++j) {
                int p = x->bvh->items[i], q = x->bvh->items[j];
                if (col_box_dist2(&x->bvh->boxes[p], &x->bvh->boxes[q]) >= x->best * x->best) continue;
                double d = x->fn(x->user, p < q ? p : q, p < q ? q : p, x->best);
                if (d < x->best) x->best = d;
            }
        return;
    }
    if (a == b) {
        nearest_rec(x, na->left, na->left);
        nearest_rec(x, na->right, na->right);
        nearest_rec(x, na->left, na->right);
        return;
    }
    // Split the inner node holding more items, nearer child first.
    bool split_a = !is_leaf(na) && (is_leaf(nb) || na->count >= nb->count);
    int c0 = split_a ? na->left : nb->left, c1 = split_a ? na->right : nb->right, other = split_a ? b : a;
    const col_box *ob = &x->bvh->nodes[other].box;
    double d0 = col_box_dist2(&x->bvh->nodes[c0].box, ob), d1 = col_box_dist2(&x->bvh->nodes[c1].box, ob);
    if (d1 < d0) {
        int t = c0;
        c0 = c1;
        c1 = t;
    }
    nearest_rec(x, c0, other);
    nearest_rec(x, c1, other);
}

double col_bvh_nearest(col_bvh *bvh, double best, col_dist_fn *fn, void *user)
{
    if (bvh->node_count == 0) return best;
    nearest_ctx x = {bvh, fn, user, best};
    nearest_rec(&x, 0, 0);
    return x.best;
}
