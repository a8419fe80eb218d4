/* base/union_find: disjoint sets over 0..n-1 (components, fans, loops).
 *
 * Union by linking the larger root under the smaller one, so a set's root
 * is always its smallest member: labels derived from roots are then
 * deterministic and independent of the union order. Path halving keeps
 * finds near constant time. Plain int arrays: no allocation inside.
 */
#ifndef SCAF_BASE_UNION_FIND_H
#define SCAF_BASE_UNION_FIND_H

/* parent: n ints; afterwards every element is its own set. */
static inline void uf_init(int *parent, int n)
{
    for (int i = 0; i < n; i++) parent[i] = i;
}

/* The root (smallest member) of x's set. */
static inline int uf_find(int *parent, int x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* Merge the sets of a and b; returns 1 if they were different sets. */
static inline int uf_union(int *parent, int a, int b)
{
    a = uf_find(parent, a);
    b = uf_find(parent, b);
    if (a == b) return 0;
    if (a < b) parent[b] = a;
    else parent[a] = b;
    return 1;
}

#endif /* SCAF_BASE_UNION_FIND_H */
