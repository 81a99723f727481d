/* unit_tui.c: the dashboard's pure parts without a terminal: a known small
 * field drawn into half-block cells in each colour mode, the mode choice,
 * sparklines, the layout's size limit, and the prompt's editing and history. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../app/tui/tui_draw.h"
#include "../app/tui/tui_layout.h"
#include "../app/tui/tui_prompt.h"
#include "test.h"

/* A 2 x 4 field (row 0 at the bottom): column 0 holds 0, 1, 2, 3 going up,
 * column 1 is outside the material below and 3 at the top. */
static const double field[8] = {0, NAN, 1, NAN, 2, NAN, 3, 3};

TEST(draw_truecolor_half_blocks) {
    tui_cell c[4]; /* 2 columns x 2 rows: each cell two vertical pixels */
    tui_draw_heatmap(field, 2, 4, 0, 3, 0, 1, 0, 1, TUI_TRUECOLOR, 2, 2, c);
    unsigned char lo[3], hi[3];
    tui_colormap(0, lo);
    tui_colormap(1, hi);
    int32_t top = hi[0] << 16 | hi[1] << 8 | hi[2], bottom = lo[0] << 16 | lo[1] << 8 | lo[2];
    /* top row: pixels at field rows 3 (upper) and 2 (lower) */
    CHECK(c[0].ch == TUI_UPPER_HALF);
    CHECK(c[0].fg == top);
    CHECK(c[0].bg == tui_color(2.0 / 3, TUI_TRUECOLOR));
    /* column 1, top row: 3 above, outside below: the upper half on the default background */
    CHECK(c[1].ch == TUI_UPPER_HALF && c[1].fg == top && c[1].bg == TUI_DEFAULT);
    /* bottom row: rows 1 and 0 of column 0 */
    CHECK(c[2].ch == TUI_UPPER_HALF && c[2].fg == tui_color(1.0 / 3, TUI_TRUECOLOR) && c[2].bg == bottom);
    /* column 1 bottom: both pixels outside the material: blank, default colours */
    CHECK(c[3].ch == ' ' && c[3].fg == TUI_DEFAULT && c[3].bg == TUI_DEFAULT);
    /* colour map ends are the documented stops */
    CHECK(lo[0] == 68 && lo[1] == 1 && lo[2] == 84);
    CHECK(hi[0] == 253 && hi[1] == 231 && hi[2] == 37);
}

TEST(draw_lower_half_when_top_outside) {
    const double f[2] = {5, NAN}; /* 1 x 2: material below, nothing above */
    tui_cell c;
    tui_draw_heatmap(f, 1, 2, 0, 10, 0, 1, 0, 1, TUI_256, 1, 1, &c);
    CHECK(c.ch == TUI_LOWER_HALF);
    CHECK(c.fg == tui_color(0.5, TUI_256));
    CHECK(c.bg == TUI_DEFAULT);
}

TEST(draw_256_palette) {
    tui_cell c[4];
    tui_draw_heatmap(field, 2, 4, 0, 3, 0, 1, 0, 1, TUI_256, 2, 2, c);
    for (int i = 0; i < 3; i++) CHECK(c[i].fg >= 16 && c[i].fg <= 255);
    /* the palette mapping: pure colours land on the cube's corners, greys on the ramp */
    unsigned char red[3] = {255, 0, 0}, white[3] = {255, 255, 255}, grey[3] = {128, 128, 128};
    CHECK(tui_rgb_to_256(red) == 196);
    CHECK(tui_rgb_to_256(white) == 231);
    CHECK(tui_rgb_to_256(grey) == 244);
}

/* A 256-colour terminal shows the colour map's hues: a coloured sample never
 * lands on the grey ramp (232..255). Matching by plain RGB distance sent the
 * map's muted blues and teals to greys, which drew grey bands across a heat
 * map. Only a colour with little chroma may become a grey. */
TEST(draw_256_keeps_hue) {
    int greys = 0, coloured = 0;
    for (int i = 0; i <= 255; i++) {
        unsigned char c[3];
        tui_colormap(i / 255.0, c);
        int mx = c[0], mn = c[0];
        for (int k = 1; k < 3; k++) mx = c[k] > mx ? c[k] : mx, mn = c[k] < mn ? c[k] : mn;
        if (mx - mn < 24) continue; /* near grey: either is fair */
        coloured++;
        const int idx = tui_rgb_to_256(c);
        if (idx >= 232) {
            if (greys < 3) printf("  map %.3f (%d, %d, %d) -> grey %d\n", i / 255.0, c[0], c[1], c[2], idx);
            greys++;
        }
    }
    printf("  %d of %d coloured samples of the map went to the grey ramp\n", greys, coloured);
    CHECK(coloured > 200);
    CHECK(greys == 0);
}

/* A collider shows grey where no material is, and never covers material. */
TEST(draw_solids_fill_empty_pixels) {
    const double f[4] = {NAN, NAN, 5, NAN}; /* 1 x 4 pixels, row 0 at the bottom: material in row 2 only */
    tui_cell c[2];
    tui_draw_heatmap(f, 1, 4, 0, 10, 0, 1, 0, 1, TUI_TRUECOLOR, 1, 2, c);
    /* cells top to bottom: [row 3 empty over row 2 material], [rows 1 and 0 empty] */
    const unsigned char solid[4] = {1, 1, 1, 1}; /* a solid everywhere (pixels top to bottom) */
    tui_cell before[2] = {c[0], c[1]};
    tui_draw_solids(c, 1, 2, solid, TUI_TRUECOLOR);
    const int32_t grey = 0x6e6e78;
    /* top cell: its upper pixel was empty -> grey; its lower pixel held material -> kept */
    CHECK(c[0].ch == TUI_UPPER_HALF && c[0].fg == grey && c[0].bg == before[0].fg);
    /* bottom cell: both pixels empty -> both grey */
    CHECK(c[1].ch == TUI_UPPER_HALF && c[1].fg == grey && c[1].bg == grey);
    /* no solid: nothing changes */
    tui_cell d[2] = {before[0], before[1]};
    const unsigned char none[4] = {0, 0, 0, 0};
    tui_draw_solids(d, 1, 2, none, TUI_TRUECOLOR);
    CHECK(d[0].ch == before[0].ch && d[0].fg == before[0].fg && d[1].ch == before[1].ch);
    /* ASCII: a hatch in empty cells only */
    tui_draw_heatmap(f, 1, 4, 0, 10, 0, 1, 0, 1, TUI_ASCII, 1, 2, c);
    tui_draw_solids(c, 1, 2, solid, TUI_ASCII);
    CHECK(c[0].ch != '/' && c[1].ch == '/');
}

/* The key bar always ends with help and quit, down to 20 columns. */
TEST(key_bar_keeps_help_and_quit) {
    for (int w = 20; w <= 140; w++) {
        const char *b = tui_key_bar(w);
        const size_t n = strlen(b);
        CHECK((int)n <= w);
        CHECK(n >= 14 && !strcmp(b + n - 14, "? help  q quit"));
    }
    CHECK(strstr(tui_key_bar(80), "c ckpt") != NULL); /* at 80 columns the compact bar keeps every key */
}

TEST(draw_ascii_density) {
    tui_cell c[4];
    tui_draw_heatmap(field, 2, 4, 0, 3, 0, 1, 0, 1, TUI_ASCII, 2, 2, c);
    /* each cell is the density of its two pixels' mean: top-left (3 + 2)/2 of 3 -> 5/6 */
    CHECK(c[0].ch == (uint32_t)tui_density_char(5.0 / 6));
    CHECK(c[2].ch == (uint32_t)tui_density_char(1.0 / 6));
    CHECK(c[1].ch == '@');           /* the maximum alone (its lower pixel is outside) */
    CHECK(c[3].ch == ' ');           /* outside */
    CHECK(tui_density_char(0) == '.'); /* the minimum is not mistaken for outside */
    for (int i = 0; i < 4; i++) CHECK(c[i].fg == TUI_DEFAULT && c[i].bg == TUI_DEFAULT);
}

TEST(draw_zoom_window) {
    /* the upper half of the field only (v from 0.5 to 1), one cell: rows 3 and 2 */
    tui_cell c;
    tui_draw_heatmap(field, 2, 4, 0, 3, 0, 0.5, 0.5, 1, TUI_TRUECOLOR, 1, 1, &c);
    CHECK(c.fg == tui_color(1, TUI_TRUECOLOR) && c.bg == tui_color(2.0 / 3, TUI_TRUECOLOR));
}

TEST(draw_uniform_field_mid_colour) {
    const double f[2] = {20, 20 + 1e-12};
    tui_cell c;
    tui_draw_heatmap(f, 1, 2, 20, 20 + 1e-12, 0, 1, 0, 1, TUI_TRUECOLOR, 1, 1, &c);
    CHECK(c.fg == tui_color(0.5, TUI_TRUECOLOR) && c.bg == c.fg);
}

/* The browning field is drawn in the crust's own map (raw dough to dark
 * brown), as pictures draw it; other fields keep the dashboard's stops. */
TEST(draw_browning_colormap) {
    unsigned char c[3];
    tui_use_colormap("browning");
    tui_colormap(0, c);
    CHECK(c[0] == 242 && c[1] == 226 && c[2] == 190);
    tui_colormap(1, c);
    CHECK(c[0] == 76 && c[1] == 38 && c[2] == 18);
    tui_use_colormap(NULL);
    tui_colormap(0, c);
    CHECK(c[0] == 68 && c[1] == 1 && c[2] == 84);
    tui_use_colormap("no_such_map"); /* an unknown name keeps the stops */
    tui_colormap(0, c);
    CHECK(c[0] == 68 && c[1] == 1 && c[2] == 84);
    tui_use_colormap(NULL);
}

TEST(pick_color_mode) {
    CHECK(tui_pick_mode("dumb", NULL, 1, 256) == TUI_PLAIN);
    CHECK(tui_pick_mode(NULL, NULL, 1, 256) == TUI_PLAIN);
    CHECK(tui_pick_mode("xterm-256color", "1", 1, 256) == TUI_ASCII); /* NO_COLOR */
    CHECK(tui_pick_mode("xterm-256color", "", 1, 256) == TUI_256);    /* empty NO_COLOR does not count */
    CHECK(tui_pick_mode("xterm-256color", NULL, 0, 256) == TUI_ASCII); /* no UTF-8: no half blocks */
    CHECK(tui_pick_mode("xterm-direct", NULL, 1, 0x1000000) == TUI_TRUECOLOR);
    CHECK(tui_pick_mode("xterm", NULL, 1, 8) == TUI_ASCII);
}

TEST(sparkline_scaling) {
    const double v[5] = {1, 2, 3, NAN, 3};
    uint32_t s[7];
    tui_sparkline(v, 5, 7, 0, s);
    CHECK(s[0] == ' ' && s[1] == ' ');       /* missing history pads on the left */
    CHECK(s[2] == 0x2581 && s[4] == 0x2588); /* min and max bars */
    CHECK(s[3] == 0x2581 + 4);               /* the middle value: round(0.5 * 7) */
    CHECK(s[5] == ' ');                      /* NaN */
    tui_sparkline(v, 5, 4, 1, s);            /* the last four (2, 3, NaN, 3) in ASCII */
    CHECK(s[0] == '_' && s[1] == '#' && s[2] == ' ' && s[3] == '#');
    tui_sparkline(v + 2, 3, 3, 1, s);        /* a flat series (3, NaN, 3) draws the lowest bar */
    CHECK(s[0] == '_' && s[1] == ' ' && s[2] == '_');
    char b[5];
    CHECK(tui_utf8(TUI_UPPER_HALF, b) == 3 && !memcmp(b, "\xe2\x96\x80", 3));
}

TEST(layout_sizes) {
    tui_layout l;
    CHECK(tui_layout_compute(79, 40, &l) == 0);
    CHECK(tui_layout_compute(120, 23, &l) == 0);
    CHECK(tui_layout_compute(60, 20, &l) == 0);
    int sizes[][2] = {{80, 24}, {120, 40}, {200, 60}};
    for (int i = 0; i < 3; i++) {
        int W = sizes[i][0], H = sizes[i][1];
        CHECK(tui_layout_compute(W, H, &l) == 1);
        CHECK(l.view[0].h >= 8 && l.view[0].w >= 38);
        CHECK(l.view[0].x + l.view[0].w < l.view[1].x);           /* side by side, apart */
        CHECK(l.view[1].x + l.view[1].w <= W);
        CHECK(l.bar[0].y == l.view[0].y + l.view[0].h);
        CHECK(l.probes.y > l.bar[0].y && l.probes.y + l.probes.h <= l.prompt.y);
        CHECK(l.log.x > l.probes.x + l.probes.w - 1 && l.log.x + l.log.w <= W);
        CHECK(l.prompt.y == H - 1);
    }
}

static void type(tui_prompt *p, const char *s) {
    for (; *s; s++) tui_prompt_key(p, *s);
}

TEST(prompt_editing) {
    tui_prompt p;
    tui_prompt_init(&p, NULL);
    type(&p, "s:oven(120)");
    tui_prompt_key(&p, TUI_KEY_LEFT);
    tui_prompt_key(&p, TUI_KEY_BACKSPACE); /* the 0 */
    type(&p, "5");
    CHECK(!strcmp(p.buf, "s:oven(125)"));
    tui_prompt_key(&p, TUI_KEY_HOME);
    type(&p, "x = ");
    tui_prompt_key(&p, TUI_KEY_END);
    tui_prompt_key(&p, TUI_KEY_DELETE_WORD_BACK); /* ')' */
    tui_prompt_key(&p, TUI_KEY_DELETE_WORD_BACK); /* '125' */
    CHECK(!strcmp(p.buf, "x = s:oven("));
    tui_prompt_key(&p, TUI_KEY_WORD_LEFT);
    CHECK(p.cur == 6);
    CHECK(tui_prompt_word_start(&p) == 4); /* "s:" counts as part of the word being completed */
    tui_prompt_key(&p, TUI_KEY_KILL_END);
    CHECK(!strcmp(p.buf, "x = s:"));
    CHECK(tui_prompt_key(&p, TUI_KEY_TAB) == TUI_PROMPT_COMPLETE);
    CHECK(tui_prompt_key(&p, TUI_KEY_ESC) == TUI_PROMPT_LEAVE);
    CHECK(tui_prompt_key(&p, TUI_KEY_ENTER) == TUI_PROMPT_SUBMIT);
    char out[64];
    tui_prompt_take(&p, out, sizeof out);
    CHECK(!strcmp(out, "x = s:") && p.len == 0);
    tui_prompt_free(&p);
}

TEST(prompt_history_file) {
    char dir[] = "/tmp/hearth_tui_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[256];
    snprintf(path, sizeof path, "%s/state/hearth/history", dir);
    tui_prompt p;
    tui_prompt_init(&p, path);
    CHECK(tui_prompt_remember(&p, "s:oven(120)") == 0);
    CHECK(tui_prompt_remember(&p, "for i = 1, 2 do\nprint(i \\ 2)\nend") == 0);
    tui_prompt_free(&p);
    tui_prompt q; /* a new session reads them back, the multi-line entry whole */
    tui_prompt_init(&q, path);
    CHECK(q.nhist == 2);
    CHECK(q.nhist == 2 && !strcmp(q.hist[1], "for i = 1, 2 do\nprint(i \\ 2)\nend"));
    tui_prompt_key(&q, TUI_KEY_UP);
    tui_prompt_key(&q, TUI_KEY_UP);
    CHECK(!strcmp(q.buf, "s:oven(120)"));
    tui_prompt_key(&q, TUI_KEY_DOWN);
    tui_prompt_key(&q, TUI_KEY_DOWN);
    CHECK(q.len == 0); /* back to the new line */
    tui_prompt_free(&q);
    /* the path: XDG_STATE_HOME first, then HOME */
    setenv("XDG_STATE_HOME", "/x/state", 1);
    CHECK(tui_history_path(path, sizeof path) && !strcmp(path, "/x/state/hearth/history"));
    unsetenv("XDG_STATE_HOME");
    setenv("HOME", "/home/u", 1);
    CHECK(tui_history_path(path, sizeof path) && !strcmp(path, "/home/u/.local/state/hearth/history"));
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
}

TEST_MAIN(T(draw_truecolor_half_blocks), T(draw_lower_half_when_top_outside), T(draw_256_palette), T(draw_256_keeps_hue),
          T(key_bar_keeps_help_and_quit), T(draw_solids_fill_empty_pixels),
          T(draw_ascii_density), T(draw_zoom_window), T(draw_uniform_field_mid_colour), T(draw_browning_colormap), T(pick_color_mode),
          T(sparkline_scaling), T(layout_sizes), T(prompt_editing), T(prompt_history_file))
