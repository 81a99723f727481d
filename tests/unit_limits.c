/* unit_limits.c: scene numbers refused before anything is allocated, and
 * scenes at the edges of what the grid can hold. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "mpm_fixture.h"

/* A collider whose shape covers the whole box: its projection used to put
 * particles outside the grid after the step's clamp, and the next sort
 * filed them in a block whose tile did not hold their stencil (a stack
 * overflow in p2g_block). The scene must run (or be refused with a message). */
static void covering_collider(int dim) {
    hearth_scene *s = fx_scene(dim, 0.05, 0.0, 1.0);
    CHECK(s);
    if (!s) return;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const double c[3] = {0.5, 0.5, dim == 3 ? 0.5 : 0.0}, h[3] = {0.1, 0.1, dim == 3 ? 0.1 : 0.0};
    CHECK(fx_box(s, m, c, h, 2, NULL) > 0);
    const double cc[3] = {0.5, 0.5, dim == 3 ? 0.5 : 0.0}, ch[3] = {2.0, 2.0, dim == 3 ? 2.0 : 0.0};
    CHECK(fx_box_collider(s, cc, ch, HEARTH_SLIP, 0.0) >= 0);
    hearth_error err;
    const hearth_status st = hearth_scene_step(s, 5, &err);
    if (st) printf("  refused: %s\n", err.msg);
    CHECK(st == HEARTH_OK || err.msg[0]);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    printf("  %d particles, %ld steps, %ld pushed back into the grid\n", stats.particles, stats.step, stats.out_of_domain);
    CHECK(st != HEARTH_OK || stats.step == 5);
    CHECK(stats.out_of_domain > 0); /* the collider did push them out */
    /* the collider's projection (after G2P's clamp) leaves particles outside
     * the grid; the sort, where their block is chosen, brings every one back */
    CHECK(mpm_sort(s, &err) == HEARTH_OK);
    const grid *g = &s->g;
    int outside = 0;
    for (int i = 0; i < s->ps.n; i++)
        for (int d = 0; d < dim; d++) {
            const double x = pcold(&s->ps, PC_X)[3 * i + d];
            outside += !(x >= g->lo[d] + g->dx && x <= g->lo[d] + (g->nn[d] - 2) * g->dx);
        }
    CHECK(outside == 0);
    hearth_scene_destroy(s);
}

TEST(covering_collider_2d) { covering_collider(2); }
TEST(covering_collider_3d) { covering_collider(3); }

TEST_MAIN(T(covering_collider_2d), T(covering_collider_3d))
