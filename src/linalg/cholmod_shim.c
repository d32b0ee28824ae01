/*
 * cholmod_shim.c: the few calls of CHOLMOD (SuiteSparse) that the sparse
 * storage of src/linalg/sparse_matrix.f90 needs, behind a flat C interface
 * of integers, doubles and arrays that src/linalg/cholmod_binding.f90 binds.
 * A C file, not Fortran interfaces to cholmod_l_*: CHOLMOD is driven through
 * structs whose layout changes between releases (cholmod_common has some
 * 300 fields); here the C compiler reads the installed cholmod.h. The 64-bit
 * version (cholmod_l_*) lets a factor hold more than 2^31 entries.
 *
 * Handles: each factorization is an entry of a table, named by a key (1, 2,
 * 3, ..., never reused), so a stale key is refused (IMPACT_CHOLMOD_NO_HANDLE)
 * instead of touching freed memory. Not thread-safe (nor is the program).
 * Return codes: the enum below (impact_cholmod_status gives CHOLMOD's
 * status of the last failure).
 */
#include <stdlib.h>
#include <string.h>
#include <cholmod.h>

/* The same in cholmod_binding.f90; FAILED: another failure of CHOLMOD. */
enum { IMPACT_CHOLMOD_OK = 0, IMPACT_CHOLMOD_NO_HANDLE = 1, IMPACT_CHOLMOD_NO_MEMORY = 2,
       IMPACT_CHOLMOD_TOO_LARGE = 3, IMPACT_CHOLMOD_INVALID = 4, IMPACT_CHOLMOD_FAILED = 5 };

/* One factorization: CHOLMOD's workspace, the matrix handed over for the
 * next analysis or factorization, the factor, and the solve's workspace. */
typedef struct {
    long long key;
    cholmod_common c;
    cholmod_sparse *A;
    cholmod_factor *L;
    cholmod_dense *X, *Y, *E;
} entry_t;

/* The ordering of the last pattern analysed anew: a matrix of the same
 * pattern (K_L for the scene's static estimate, then K_L + 4/dt^2 M for the
 * run) is analysed with it, which skips the ordering's search (AMD and
 * METIS, about a third of a factorization of a plate) and gives the same
 * factor structure. Identified by its order, entries and a hash of the
 * pattern (a collision would only cost fill: any permutation is valid). */
static struct {
    long long n, nnz;
    unsigned long long hash;
    SuiteSparse_long *perm;
} order_cache = {0, 0, 0, NULL};

static entry_t **table = NULL;   /* live entries, table[0 .. live-1] */
static size_t live = 0, capacity = 0;
static long long last_key = 0;
static int last_status = CHOLMOD_OK;   /* CHOLMOD status of the last failure */

/* The entry of a key, or NULL. */
static entry_t *find(long long key)
{
    size_t k;
    for (k = 0; k < live; k++)
        if (table[k]->key == key) return table[k];
    return NULL;
}

/* The return code for CHOLMOD's status after a failed call. */
static int code_of(const cholmod_common *c)
{
    last_status = c->status;
    switch (c->status) {
    case CHOLMOD_OUT_OF_MEMORY: return IMPACT_CHOLMOD_NO_MEMORY;
    case CHOLMOD_TOO_LARGE:     return IMPACT_CHOLMOD_TOO_LARGE;
    case CHOLMOD_INVALID:       return IMPACT_CHOLMOD_INVALID;
    default:                    return IMPACT_CHOLMOD_FAILED;
    }
}

/* A new, empty handle, an entry in the table with CHOLMOD started:
 * supernodal Cholesky, the default choice of fill-reducing ordering (AMD,
 * and METIS or nested dissection when AMD leaves much fill), nothing printed
 * (every failure is returned). Its key, or 0 when out of memory. */
long long impact_cholmod_new(void)
{
    entry_t *e;
    if (live == capacity) {
        size_t grown = capacity == 0 ? 8 : 2 * capacity;
        entry_t **t = realloc(table, grown * sizeof *t);
        if (t == NULL) return 0;
        table = t;
        capacity = grown;
    }
    e = calloc(1, sizeof *e);
    if (e == NULL) return 0;
    if (!cholmod_l_start(&e->c)) {
        free(e);
        return 0;
    }
    e->c.supernodal = CHOLMOD_SUPERNODAL;
    e->c.print = 0;
    e->key = ++last_key;
    table[live++] = e;
    return e->key;
}

/* Release a handle and all it holds; a key not (or no longer) in the table
 * is ignored. */
void impact_cholmod_free(long long key)
{
    size_t k;
    for (k = 0; k < live; k++) {
        entry_t *e = table[k];
        if (e->key != key) continue;
        cholmod_l_free_sparse(&e->A, &e->c);
        cholmod_l_free_factor(&e->L, &e->c);
        cholmod_l_free_dense(&e->X, &e->c);
        cholmod_l_free_dense(&e->Y, &e->c);
        cholmod_l_free_dense(&e->E, &e->c);
        cholmod_l_finish(&e->c);
        free(e);
        table[k] = table[--live];
        return;
    }
}

/* Number of live handles (for the tests: every factorization released). */
long long impact_cholmod_live(void)
{
    return (long long) live;
}

/* CHOLMOD's status of the last failure (CHOLMOD_OUT_OF_MEMORY, ...). */
int impact_cholmod_status(void)
{
    return last_status;
}

/* A new handle holding a copy of the factor (symbolic or numeric) of key;
 * *copy = its key, 0 when key holds no factor. */
int impact_cholmod_copy(long long key, long long *copy)
{
    entry_t *e = find(key), *d;
    *copy = 0;
    if (e == NULL) return IMPACT_CHOLMOD_NO_HANDLE;
    if (e->L == NULL) return IMPACT_CHOLMOD_OK;
    d = find(impact_cholmod_new());      /* (find(0): NULL) */
    if (d == NULL) return IMPACT_CHOLMOD_NO_MEMORY;
    d->L = cholmod_l_copy_factor(e->L, &d->c);
    if (d->L == NULL) {
        int code = code_of(&d->c);
        impact_cholmod_free(d->key);
        return code;
    }
    *copy = d->key;
    return IMPACT_CHOLMOD_OK;
}

/* Hand over the upper triangle of a symmetric n x n matrix in compressed
 * columns with 1-based indices: the rows of column j are rowind[colptr[j-1]
 * - 1 .. colptr[j] - 2], ascending, with the values val. Kept until the
 * next factorization. */
int impact_cholmod_set_matrix(long long key, long long n, const long long *colptr,
                              const int *rowind, const double *val)
{
    entry_t *e = find(key);
    SuiteSparse_long *p, *i;
    long long j, k, nnz;
    if (e == NULL) return IMPACT_CHOLMOD_NO_HANDLE;
    if (n < 1 || colptr[0] != 1 || colptr[n] < 1) return IMPACT_CHOLMOD_INVALID;
    nnz = colptr[n] - 1;
    cholmod_l_free_sparse(&e->A, &e->c);
    e->A = cholmod_l_allocate_sparse((size_t) n, (size_t) n, (size_t) nnz, 1, 1, 1, CHOLMOD_REAL, &e->c);
    if (e->A == NULL) return code_of(&e->c);
    p = e->A->p;
    i = e->A->i;
    for (j = 0; j <= n; j++) p[j] = (SuiteSparse_long) (colptr[j] - 1);
    for (k = 0; k < nnz; k++) i[k] = (SuiteSparse_long) (rowind[k] - 1);
    memcpy(e->A->x, val, (size_t) nnz * sizeof(double));
    return IMPACT_CHOLMOD_OK;
}

/* FNV-1a hash of the pattern of A (column starts and row indices). */
static unsigned long long pattern_hash(const cholmod_sparse *A)
{
    const SuiteSparse_long *p = A->p, *i = A->i;
    unsigned long long h = 14695981039346656037ULL;
    size_t k, n = A->ncol, nnz = (size_t) p[n];
    for (k = 0; k <= n; k++) h = (h ^ (unsigned long long) p[k]) * 1099511628211ULL;
    for (k = 0; k < nnz; k++) h = (h ^ (unsigned long long) i[k]) * 1099511628211ULL;
    return h;
}

/* The analysis of A: with the cached ordering when A has its pattern
 * (given permutation, already postordered), else CHOLMOD's own choice,
 * whose ordering is then cached. */
static cholmod_factor *analyse(cholmod_sparse *A, cholmod_common *c)
{
    long long n = (long long) A->ncol, nnz = (long long) ((SuiteSparse_long *) A->p)[A->ncol];
    unsigned long long hash = pattern_hash(A);
    cholmod_factor *L;
    if (order_cache.perm != NULL && order_cache.n == n && order_cache.nnz == nnz && order_cache.hash == hash) {
        int nmethods = c->nmethods, ordering = c->method[0].ordering, postorder = c->postorder;
        c->nmethods = 1;
        c->method[0].ordering = CHOLMOD_GIVEN;
        c->postorder = 0;
        L = cholmod_l_analyze_p(A, order_cache.perm, NULL, 0, c);
        c->nmethods = nmethods;
        c->method[0].ordering = ordering;
        c->postorder = postorder;
        return L;
    }
    L = cholmod_l_analyze(A, c);
    SuiteSparse_long *perm = L == NULL ? NULL : malloc((size_t) n * sizeof *perm);
    if (perm == NULL) return L;     /* (no memory for the cache: analysed all the same) */
    memcpy(perm, L->Perm, (size_t) n * sizeof *perm);
    free(order_cache.perm);
    order_cache.perm = perm;
    order_cache.n = n;
    order_cache.nnz = nnz;
    order_cache.hash = hash;
    return L;
}

/* The symbolic factorization of the matrix handed over: the fill-reducing
 * ordering and the structure of the factor, before any number is computed.
 * *lnz: nonzeros of L; *flops: floating-point operations of the numeric
 * factorization; *bytes: the memory the numeric factor will take (its reals
 * and integers). A symbolic factor held already is replaced. */
int impact_cholmod_analyze(long long key, double *lnz, double *flops, double *bytes)
{
    entry_t *e = find(key);
    cholmod_factor *L;
    if (e == NULL) return IMPACT_CHOLMOD_NO_HANDLE;
    if (e->A == NULL) return IMPACT_CHOLMOD_INVALID;
    cholmod_l_free_factor(&e->L, &e->c);
    L = analyse(e->A, &e->c);
    if (L == NULL) return code_of(&e->c);
    e->L = L;
    *lnz = e->c.lnz;
    *flops = e->c.fl;
    if (L->is_super)
        *bytes = (double) L->xsize * sizeof(double)
               + ((double) L->ssize + 4.0 * (double) L->nsuper + 2.0 * (double) L->n)
                 * sizeof(SuiteSparse_long);
    else
        *bytes = e->c.lnz * (sizeof(double) + sizeof(SuiteSparse_long));
    cholmod_l_free_work(&e->c);
    return IMPACT_CHOLMOD_OK;
}

/* The numeric factorization A = L L^T (A permuted) of the matrix handed
 * over, on the analysed structure (a numeric factor held already is
 * overwritten: a refactorization of a matrix of the same pattern). The
 * matrix and CHOLMOD's workspace are released afterwards. *minor: the
 * 1-based column, in the order of elimination, at which L L^T failed
 * (matrix not positive definite), n + 1 when it did not. */
int impact_cholmod_factorize(long long key, long long *minor)
{
    entry_t *e = find(key);
    int ok;
    *minor = 0;
    if (e == NULL) return IMPACT_CHOLMOD_NO_HANDLE;
    if (e->A == NULL || e->A->xtype != CHOLMOD_REAL || e->L == NULL) return IMPACT_CHOLMOD_INVALID;
    ok = cholmod_l_factorize(e->A, e->L, &e->c);
    cholmod_l_free_sparse(&e->A, &e->c);
    cholmod_l_free_work(&e->c);
    if (!ok || (e->c.status < CHOLMOD_OK)) return code_of(&e->c);
    *minor = (long long) e->L->minor + 1;
    return IMPACT_CHOLMOD_OK;
}

/* The diagonal of L in the order of elimination, diag[k] = L(k,k), and the
 * permutation, perm[k] = the 1-based equation eliminated k-th (k = 0..n-1).
 * Only the columns before L->minor are defined. */
int impact_cholmod_diagonal(long long key, long long n, double *diag, long long *perm)
{
    entry_t *e = find(key);
    cholmod_factor *L;
    const double *x;
    long long k;
    if (e == NULL) return IMPACT_CHOLMOD_NO_HANDLE;
    L = e->L;
    if (L == NULL || (long long) L->n != n || L->xtype != CHOLMOD_REAL) return IMPACT_CHOLMOD_INVALID;
    x = L->x;
    memset(diag, 0, (size_t) n * sizeof *diag);   /* (0.0) */
    for (k = 0; k < n; k++) perm[k] = (long long) ((const SuiteSparse_long *) L->Perm)[k] + 1;
    if (L->is_super) {
        const SuiteSparse_long *super = L->super, *pi = L->pi, *px = L->px;
        size_t s;
        for (s = 0; s < L->nsuper; s++) {
            SuiteSparse_long k1 = super[s], k2 = super[s + 1], nsrow = pi[s + 1] - pi[s], c;
            for (c = 0; c < k2 - k1; c++) diag[k1 + c] = x[px[s] + c + c * nsrow];
        }
    } else {
        const SuiteSparse_long *p = L->p;
        for (k = 0; k < n; k++) diag[k] = x[p[k]];
    }
    return IMPACT_CHOLMOD_OK;
}

/* Solve A x = b with the numeric factor; b (n) is overwritten by x. The
 * solve's workspace stays with the handle for the next call. */
int impact_cholmod_solve(long long key, long long n, double *b)
{
    entry_t *e = find(key);
    if (e == NULL) return IMPACT_CHOLMOD_NO_HANDLE;
    if (e->L == NULL || (long long) e->L->n != n || e->L->xtype != CHOLMOD_REAL) return IMPACT_CHOLMOD_INVALID;
    cholmod_dense B = {.nrow = (size_t) n, .ncol = 1, .nzmax = (size_t) n, .d = (size_t) n, .x = b,
                       .xtype = CHOLMOD_REAL, .dtype = CHOLMOD_DOUBLE};
    if (!cholmod_l_solve2(CHOLMOD_A, e->L, &B, NULL, &e->X, NULL, &e->Y, &e->E, &e->c))
        return code_of(&e->c);
    memcpy(b, e->X->x, (size_t) n * sizeof(double));
    return IMPACT_CHOLMOD_OK;
}
