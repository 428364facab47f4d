// Exact natural numbers for state counts, on GMP's low-level mpn functions: they work in caller
// buffers, so every limb lives in memory from the counted allocator (the mpz layer would use
// GMP's own allocator, invisible to ori_alloc_live_count).
#include "layers_internal.h"

#include <stdlib.h>

void ori__csr_free(ori__csr *c)
{
    ori__free(c->off);
    ori__free(c->items);
    c->off = NULL;
    c->items = NULL;
    c->rows = 0;
}

void ori__nat_init(ori__nat *x)
{
    x->n = 0;
    x->cap = 0;
    x->one = 0;
    x->d = NULL;
}

void ori__nat_free(ori__nat *x)
{
    ori__free(x->d);
    ori__nat_init(x);
}

// Room for n limbs; keeps the value (its first min(n, x->n) limbs).
static mp_limb_t *reserve(ori__nat *x, int n)
{
    if (n <= 1 && !x->d) return &x->one;
    if (x->d && x->cap >= n) return x->d;
    int cap = n < 4 ? 4 : n + n / 2;
    mp_limb_t *d = ori__alloc(sizeof(mp_limb_t) * (size_t)cap);
    if (x->n > 0) memcpy(d, ori__nat_limbs(x), sizeof(mp_limb_t) * (size_t)x->n);
    ori__free(x->d);
    x->d = d;
    x->cap = cap;
    return d;
}

static void normalize(ori__nat *x)
{
    const mp_limb_t *d = ori__nat_limbs(x);
    while (x->n > 0 && d[x->n - 1] == 0) x->n--;
}

void ori__nat_set_u64(ori__nat *x, uint64_t v)
{
    mp_limb_t *d = reserve(x, 1);
    d[0] = (mp_limb_t)v;
    x->n = v ? 1 : 0;
}

void ori__nat_copy(ori__nat *dst, const ori__nat *src)
{
    if (dst == src) return;
    mp_limb_t *d = reserve(dst, src->n);
    if (src->n) memcpy(d, ori__nat_limbs(src), sizeof(mp_limb_t) * (size_t)src->n);
    dst->n = src->n;
}

bool ori__nat_is_zero(const ori__nat *x) { return x->n == 0; }

int ori__nat_cmp(const ori__nat *a, const ori__nat *b)
{
    if (a->n != b->n) return a->n < b->n ? -1 : 1;
    if (a->n == 0) return 0;
    return mpn_cmp(ori__nat_limbs(a), ori__nat_limbs(b), a->n);
}

int ori__nat_cmp_u64(const ori__nat *a, uint64_t v)
{
    if (a->n > 1) return 1;
    uint64_t x = a->n ? (uint64_t)ori__nat_limbs(a)[0] : 0;
    return x < v ? -1 : x > v ? 1 : 0;
}

void ori__nat_add(ori__nat *acc, const ori__nat *b)
{
    if (b->n == 0) return;
    if (acc->n == 0) {
        ori__nat_copy(acc, b);
        return;
    }
    int n = acc->n > b->n ? acc->n : b->n;
    if (acc->n == 1 && b->n == 1) {
        mp_limb_t s = acc->one + ori__nat_limbs(b)[0];
        if (!acc->d && s >= acc->one) { // no carry: stays inline
            acc->one = s;
            return;
        }
    }
    mp_limb_t *d = reserve(acc, n + 1);
    mp_limb_t carry;
    if (acc->n >= b->n) carry = mpn_add(d, d, acc->n, ori__nat_limbs(b), b->n);
    else {
        // acc is the shorter: add it into a copy of b.
        mp_limb_t *t = ori__alloc(sizeof(mp_limb_t) * (size_t)b->n);
        memcpy(t, ori__nat_limbs(b), sizeof(mp_limb_t) * (size_t)b->n);
        carry = mpn_add(d, t, b->n, d, acc->n);
        ori__free(t);
    }
    d[n] = carry;
    acc->n = n + 1;
    normalize(acc);
}

void ori__nat_sub(ori__nat *acc, const ori__nat *b)
{
    ORI_ASSERT(ori__nat_cmp(acc, b) >= 0);
    if (b->n == 0) return;
    mp_limb_t *d = (mp_limb_t *)ori__nat_limbs(acc);
    mpn_sub(d, d, acc->n, ori__nat_limbs(b), b->n);
    normalize(acc);
}

void ori__nat_mul(ori__nat *acc, const ori__nat *b)
{
    if (acc->n == 0) return;
    if (b->n == 0) {
        acc->n = 0;
        return;
    }
    if (acc->n == 1 && b->n == 1 && !acc->d) {
        mp_limb_t lo, a0 = acc->one;
        if (mpn_mul_1(&lo, &a0, 1, ori__nat_limbs(b)[0]) == 0) {
            acc->one = lo;
            return;
        }
    }
    int an = acc->n, bn = b->n;
    mp_limb_t *r = ori__alloc(sizeof(mp_limb_t) * (size_t)(an + bn));
    if (an >= bn) mpn_mul(r, ori__nat_limbs(acc), an, ori__nat_limbs(b), bn);
    else mpn_mul(r, ori__nat_limbs(b), bn, ori__nat_limbs(acc), an);
    mp_limb_t *d = reserve(acc, an + bn);
    memcpy(d, r, sizeof(mp_limb_t) * (size_t)(an + bn));
    ori__free(r);
    acc->n = an + bn;
    normalize(acc);
}

void ori__nat_divmod(ori__nat *q, ori__nat *r, const ori__nat *a, const ori__nat *b)
{
    ORI_ASSERT(b->n > 0 && q != r);
    if (ori__nat_cmp(a, b) < 0) {
        ori__nat_copy(r, a);
        ori__nat_set_u64(q, 0);
        return;
    }
    int an = a->n, bn = b->n;
    mp_limb_t *qd = ori__alloc(sizeof(mp_limb_t) * (size_t)(an - bn + 1));
    mp_limb_t *rd = ori__alloc(sizeof(mp_limb_t) * (size_t)bn);
    mpn_tdiv_qr(qd, rd, 0, ori__nat_limbs(a), an, ori__nat_limbs(b), bn);
    mp_limb_t *d = reserve(q, an - bn + 1);
    memcpy(d, qd, sizeof(mp_limb_t) * (size_t)(an - bn + 1));
    q->n = an - bn + 1;
    normalize(q);
    d = reserve(r, bn);
    memcpy(d, rd, sizeof(mp_limb_t) * (size_t)bn);
    r->n = bn;
    normalize(r);
    ori__free(qd);
    ori__free(rd);
}

char *ori__nat_to_decimal(const ori__nat *x)
{
    if (x->n == 0) return ori__strdup("0");
    // 64 bits are at most 20 decimal digits; mpn_get_str clobbers its input (and wants one
    // spare limb), so it works on a copy.
    size_t cap = (size_t)x->n * 20 + 2;
    unsigned char *digits = ori__alloc(cap);
    mp_limb_t *t = ori__alloc(sizeof(mp_limb_t) * (size_t)(x->n + 1));
    memcpy(t, ori__nat_limbs(x), sizeof(mp_limb_t) * (size_t)x->n);
    size_t len = mpn_get_str(digits, 10, t, x->n);
    ori__free(t);
    size_t skip = 0;
    while (skip + 1 < len && digits[skip] == 0) skip++;
    char *s = ori__alloc(len - skip + 1);
    for (size_t i = skip; i < len; ++i) s[i - skip] = (char)('0' + digits[i]);
    s[len - skip] = '\0';
    ori__free(digits);
    return s;
}

bool ori__nat_from_decimal(ori__nat *x, const char *s)
{
    size_t len = strlen(s);
    if (len == 0) return false;
    for (size_t i = 0; i < len; ++i)
        if (s[i] < '0' || s[i] > '9') return false;
    while (len > 1 && *s == '0') {
        s++;
        len--;
    }
    if (len == 1 && *s == '0') {
        ori__nat_set_u64(x, 0);
        return true;
    }
    unsigned char *digits = ori__alloc(len);
    for (size_t i = 0; i < len; ++i) digits[i] = (unsigned char)(s[i] - '0');
    int limbs = (int)(len / 19 + 2);
    mp_limb_t *t = ori__alloc(sizeof(mp_limb_t) * (size_t)limbs);
    mp_size_t n = mpn_set_str(t, digits, len, 10);
    mp_limb_t *d = reserve(x, (int)n);
    memcpy(d, t, sizeof(mp_limb_t) * (size_t)n);
    x->n = (int)n;
    normalize(x);
    ori__free(t);
    ori__free(digits);
    return true;
}
