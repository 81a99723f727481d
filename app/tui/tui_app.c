/* tui_app.c: the dashboard's loop: keys, stepping within a time budget per
 * redraw, Lua jobs, saving, quitting.
 *
 * One thread. The simulation never waits on the screen: while running, the
 * loop steps until the next redraw is due, and redraws are at most 30 a
 * second and spaced so drawing takes at most DRAW_SHARE of the wall time
 * (a big scene's slice probes cost more than a small scene's). A thread per
 * simulation was the alternative; it would need every Lua command to lock the
 * scene, and Lua is not thread-safe, so the budget wins.
 *
 * Scene files and prompt commands run as Lua coroutines ("jobs"); with
 * hl_options.yield_steps set, s:run and s:step yield after every step
 * (hearth_scene_advance_steps(s, t_end, 1)), so the loop steps a job or the
 * bare scene until the next redraw is due, and a long s:run{...} typed at the
 * prompt never freezes the screen; Space pauses it. Errors and guard stops
 * pause the run and go to the log. The terminal is restored on q,
 * Ctrl-C/SIGTERM/SIGHUP (a flag the loop reads) and crash signals (a handler
 * calls endwin and re-raises: tui_screen.c). Truecolor needs a terminal
 * description with direct colour (COLORS >= 2^24); otherwise 256 colours
 * (tui_draw.c picks the mode). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "tui_app.h"
#include "tui_screen.h"

#define FRAME_MIN (1.0 / 30) /* redraws per second at most: 30 */
#define DRAW_SHARE 0.025     /* drawing's share of the wall time while running: 5% of the step time is the budget */

double tui_wall(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void refresh_scene(tui_app *a) {
    hearth_scene *s = tui_lua_scene(&a->lua);
    if (s != a->s) { /* a new scene (h.scene, h.load at the prompt): start its views afresh */
        a->s = s;
        a->nfp = a->npins = 0;
        a->field[0][0] = a->field[1][0] = '\0';
        a->sampled_step = -1;
        a->probed[0].valid = a->probed[1].valid = 0;
        if (s) {
            const hearth_scene_def *d = hearth_scene_get_def(s);
            for (int k = 0; k < 3; k++) a->cursor[k] = 0.5 * (d->lo[k] + d->hi[k]), a->at[k] = 0.5;
            a->axis = 2;
            int n = hearth_scene_particle_count(s); /* the probe cursor starts in the material: its centroid */
            const double *x = hearth_scene_positions(s);
            if (n > 0) {
                double c[3] = {0, 0, 0};
                for (int i = 0; i < n; i++)
                    for (int k = 0; k < 3; k++) c[k] += x[3 * i + k] / n;
                memcpy(a->cursor, c, sizeof c);
                if (d->dim == 3) a->at[2] = (c[2] - d->lo[2]) / (d->hi[2] - d->lo[2]);
            }
        }
    }
    tui_default_fields(a);
}

static void pause_run(tui_app *a) { a->running = 0; }

/* what a Lua action came to: errors and guard stops pause the run */
static void after_lua(tui_app *a, tui_lua_result r) {
    if (r == TUI_LUA_ERROR || r == TUI_LUA_GUARD) pause_run(a);
    refresh_scene(a);
}

int tui_step(tui_app *a) {
    if (a->lua.njobs) {
        tui_lua_result r = tui_lua_resume(&a->lua);
        a->unsaved = 1;
        if (r == TUI_LUA_WAITING) return 0;
        after_lua(a, r);
        if (a->lua.njobs == 0) { /* the last run finished */
            if (r == TUI_LUA_DONE) {
                hearth_stats st;
                if (a->s) hearth_scene_stats(a->s, &st);
                tui_log_add(&a->log, "the scene's run finished at t = %.5g s; Space steps on", a->s ? st.t : 0.0);
            }
            if (a->opt.exit_when_done) a->quit = 1;
            pause_run(a);
            return 1;
        }
        return r == TUI_LUA_DONE ? 0 : 1;
    }
    if (!a->s) {
        pause_run(a);
        return 1;
    }
    hearth_error err;
    hearth_status st = hearth_scene_step(a->s, 1, &err);
    a->unsaved = 1;
    if (st == HEARTH_ERR_GUARD) {
        tui_log_add(&a->log, "the stability guard stopped the run (paused):\n  %s", err.msg);
        pause_run(a);
        return 1;
    }
    if (st) {
        tui_log_add(&a->log, "error: %s", err.msg);
        pause_run(a);
        return 1;
    }
    return 0;
}

static void save_views(tui_app *a) {
    if (!a->s) return;
    hearth_stats st;
    hearth_scene_stats(a->s, &st);
    const hearth_scene_def *d = hearth_scene_get_def(a->s);
    double at = d->lo[a->axis] + a->at[a->axis] * (d->hi[a->axis] - d->lo[a->axis]);
    char path[2][4400];
    static const char *side[2] = {"left", "right"};
    for (int k = 0; k < 2; k++) {
        snprintf(path[k], sizeof path[k], "%s/%s_%s_%06ld.png", a->opt.lua.out_dir, side[k], a->field[k], st.step);
        hearth_error err;
        if (hearth_render_slice(a->s, a->field[k], d->dim == 2 ? 2 : a->axis, at, path[k], 800, &err)) {
            tui_log_add(&a->log, "error: saving the %s view: %s", side[k], err.msg);
            return;
        }
    }
    tui_log_add(&a->log, "saved %s and %s", path[0], path[1]);
}

static int checkpoint(tui_app *a) {
    if (!a->s) return -1;
    hearth_stats st;
    hearth_scene_stats(a->s, &st);
    char path[4400];
    snprintf(path, sizeof path, "%s/checkpoint_%06ld.bin", a->opt.lua.out_dir, st.step);
    hearth_error err;
    if (hearth_scene_save(a->s, path, &err)) {
        tui_log_add(&a->log, "error: checkpoint: %s", err.msg);
        return -1;
    }
    a->unsaved = 0;
    tui_log_add(&a->log, "checkpoint %s (t = %.5g s); h.load(\"%s\") restores it", path, st.t, path);
    return 0;
}

static void cycle_field(tui_app *a, int k) {
    char names[TUI_MAX_FIELDS][32];
    int n = tui_scalar_fields(a->s, names, TUI_MAX_FIELDS);
    if (n == 0) return;
    int i = 0;
    while (i < n && strcmp(names[i], a->field[k])) i++;
    snprintf(a->field[k], sizeof a->field[k], "%s", names[(i + 1) % n]);
}

static void move_cursor(tui_app *a, int du, int dv) {
    if (!a->s) return;
    const hearth_scene_def *d = hearth_scene_get_def(a->s);
    int u = a->axis == 0 ? 1 : 0, v = a->axis == 2 ? 1 : 2;
    double step = 2 * d->dx / a->zoom; /* about a cell of the view at zoom 1 */
    a->cursor[u] = fmin(fmax(a->cursor[u] + du * step, d->lo[u]), d->hi[u]);
    a->cursor[v] = fmin(fmax(a->cursor[v] + dv * step, d->lo[v]), d->hi[v]);
}

static void pin(tui_app *a) {
    if (!a->s) return;
    if (a->npins == TUI_MAX_PINS) { /* the oldest goes */
        memmove(a->pin, a->pin + 1, sizeof a->pin[0] * (TUI_MAX_PINS - 1));
        memmove(a->pin_probe, a->pin_probe + 1, sizeof a->pin_probe[0] * (TUI_MAX_PINS - 1));
        a->npins--;
    }
    memcpy(a->pin[a->npins], a->cursor, sizeof a->cursor);
    tui_field_probe *p = &a->pin_probe[a->npins];
    memset(p, 0, sizeof *p);
    snprintf(p->name, sizeof p->name, "%s", a->field[0]);
    a->npins++;
    tui_log_add(&a->log, "pinned probe %d: %s at (%.3g, %.3g, %.3g) m", a->npins, p->name, a->cursor[0], a->cursor[1],
                a->cursor[2]);
}

static void complete(tui_app *a) {
    tui_prompt *p = &a->prompt;
    int ws = tui_prompt_word_start(p);
    char word[256];
    int wl = p->cur - ws;
    if (wl >= (int)sizeof word) return;
    memcpy(word, p->buf + ws, (size_t)wl);
    word[wl] = '\0';
    char cands[64][64];
    int n = tui_lua_complete(&a->lua, word, cands, 64);
    if (n == 0) return;
    size_t common = strlen(cands[0]);
    for (int i = 1; i < n; i++) {
        size_t j = 0;
        while (j < common && cands[i][j] == cands[0][j]) j++;
        common = j;
    }
    if (common > (size_t)wl) {
        char ins[64];
        snprintf(ins, sizeof ins, "%.*s", (int)(common - (size_t)wl), cands[0] + wl);
        tui_prompt_insert(p, ins);
    }
    if (n > 1) {
        char list[1024] = "";
        for (int i = 0; i < n && strlen(list) < 900; i++) {
            strcat(list, cands[i]);
            strcat(list, "  ");
        }
        tui_log_add(&a->log, "%s%s", list, n == 64 ? "..." : "");
    }
}

static void submit(tui_app *a) {
    char line[TUI_PROMPT_MAX];
    tui_prompt_take(&a->prompt, line, sizeof line);
    tui_log_add(&a->log, "%s %s", a->chunk[0] ? ">>" : ">", line);
    size_t cl = strlen(a->chunk);
    snprintf(a->chunk + cl, sizeof a->chunk - cl, "%s%s", cl ? "\n" : "", line);
    tui_lua_result r = tui_lua_eval(&a->lua, line);
    if (r == TUI_LUA_MORE) return;
    if (a->chunk[strspn(a->chunk, " \n")]) tui_prompt_remember(&a->prompt, a->chunk);
    a->chunk[0] = '\0';
    a->unsaved = 1;
    if (r == TUI_LUA_WAITING) a->running = 1; /* the command started a run: watch it */
    after_lua(a, r);
    tui_sample_probes(a);
}

static void key(tui_app *a, int k) {
    if (k == TUI_SCREEN_RESIZE) return;
    if (a->help) { /* any key closes the help */
        a->help = 0;
        return;
    }
    if (a->ask_quit) {
        a->ask_quit = 0;
        if (k == 'y' || k == 'q') a->quit = 1;
        else if (k == 'c' && checkpoint(a) == 0) a->quit = 1;
        return;
    }
    if (a->prompt_focus) {
        tui_prompt_action act = tui_prompt_key(&a->prompt, k);
        if (act == TUI_PROMPT_SUBMIT) submit(a);
        else if (act == TUI_PROMPT_COMPLETE) complete(a);
        else if (act == TUI_PROMPT_LEAVE) {
            a->prompt_focus = 0;
            if (a->chunk[0]) tui_log_add(&a->log, "(unfinished statement dropped)");
            a->chunk[0] = '\0';
            tui_lua_discard(&a->lua);
        }
        return;
    }
    const hearth_scene_def *d = a->s ? hearth_scene_get_def(a->s) : NULL;
    switch (k) {
    case ' ': a->running = !a->running; break;
    case 'n':
        a->running = 0;
        tui_step(a);
        tui_sample_probes(a);
        break;
    case 'f': if (a->s) cycle_field(a, 0); break;
    case 'F': if (a->s) cycle_field(a, 1); break;
    case '[': case ']':
        if (d && d->dim == 3) {
            a->at[a->axis] = fmin(fmax(a->at[a->axis] + (k == ']' ? 1 : -1) / 32.0, 0), 1);
        } else tui_log_add(&a->log, "a 2D scene has one plane: the views show the whole domain");
        break;
    case 'x': case 'y': case 'z':
        if (d && d->dim == 3) a->axis = k - 'x';
        else tui_log_add(&a->log, "a 2D scene has one plane: the views show the whole domain");
        break;
    case TUI_KEY_LEFT: move_cursor(a, -1, 0); tui_sample_probes(a); break;
    case TUI_KEY_RIGHT: move_cursor(a, 1, 0); tui_sample_probes(a); break;
    case TUI_KEY_UP: move_cursor(a, 0, 1); tui_sample_probes(a); break;
    case TUI_KEY_DOWN: move_cursor(a, 0, -1); tui_sample_probes(a); break;
    case 'p': pin(a); tui_sample_probes(a); break;
    case TUI_KEY_PAGE_DOWN: case '>': /* the probe panel's next page of fields (tui_view.c clamps it) */
        a->probe_first += a->probe_page > 0 ? a->probe_page : 1;
        break;
    case TUI_KEY_PAGE_UP: case '<':
        a->probe_first -= a->probe_page > 0 ? a->probe_page : 1;
        if (a->probe_first < 0) a->probe_first = 0;
        break;
    case '+': case '=': if (a->zoom < 8) a->zoom *= 2; break;
    case '-': case '_': if (a->zoom > 1) a->zoom /= 2; break;
    case 's': save_views(a); break;
    case 'c': checkpoint(a); break;
    case ':': case TUI_KEY_TAB: a->prompt_focus = 1; break;
    case '?': a->help = 1; break;
    case 'q':
        if (a->unsaved) a->ask_quit = 1;
        else a->quit = 1;
        break;
    default: break;
    }
}

static void app_free(tui_app *a) {
    tui_lua_close(&a->lua);
    tui_prompt_free(&a->prompt);
    free(a->slice[0]);
    free(a->slice[1]);
    free(a->cells);
}

/* the scene file's first part (building the scene) runs at once */
static int app_start(tui_app *a) {
    if (tui_lua_open(&a->lua, &a->opt.lua, &a->log)) return -1;
    if (a->opt.scene) {
        if (tui_lua_start_file(&a->lua, a->opt.scene) == 0) after_lua(a, tui_lua_resume(&a->lua));
    } else if (a->opt.builtin) {
        tui_lua_adopt(&a->lua, a->opt.builtin);
    }
    tui_lua_globals(&a->lua);
    refresh_scene(a);
    tui_sample_probes(a);
    a->running = a->opt.play;
    tui_log_add(&a->log, "hearth %s: %s. Space runs, ? shows the keys, : opens the Lua prompt.", HEARTH_VERSION,
                a->opt.name);
    if (a->lua.njobs)
        tui_log_add(&a->log, a->running ? "the scene's run is running (--play); Space pauses it"
                                        : "the scene's run is waiting: Space starts it");
    return 0;
}

int tui_run(const tui_options *o) {
    tui_app *a = calloc(1, sizeof *a);
    if (!a) return 1;
    a->opt = *o;
    a->opt.lua.quiet = 1;
    a->opt.lua.yield_steps = 1;
    a->zoom = 1;
    a->axis = 2;
    a->sampled_step = -1;
    char hist[4096];
    tui_prompt_init(&a->prompt, tui_history_path(hist, sizeof hist) ? hist : NULL);

    const char *term = getenv("TERM");
    if (tui_pick_mode(term, NULL, 1, 256) == TUI_PLAIN) { /* TERM=dumb: lines, no screen */
        a->mode = TUI_PLAIN;
        int st = app_start(a) ? 1 : tui_lines_run(a);
        app_free(a);
        free(a);
        return st;
    }
    if (tui_screen_open(&a->mode)) {
        fprintf(stderr, "hearth: cannot start the terminal screen (TERM=%s)\n", term ? term : "");
        free(a);
        return 1;
    }
    if (app_start(a)) {
        tui_screen_close();
        for (long i = a->log.count - 1; i >= 0; i--) fprintf(stderr, "%s\n", tui_log_get(&a->log, i));
        app_free(a);
        free(a);
        return 1;
    }
    if (tui_screen_color_note()[0]) tui_log_add(&a->log, "%s", tui_screen_color_note());
    double next_draw = 0, last_draw = 0;
    long seen_log = -1;
    int dirty = 1, keyed = 0;
    a->rate_wall = tui_wall();
    if (a->s) {
        hearth_stats st;
        hearth_scene_stats(a->s, &st);
        a->rate_step = st.step;
    }
    while (!a->quit) {
        if (tui_screen_interrupted()) {
            a->status = 130;
            break;
        }
        double now = tui_wall();
        /* keys: all that are waiting; when paused, wait for one (the screen has nothing else to do) */
        int wait_ms = a->running ? 0 : dirty || keyed ? (int)fmax(0, fmin(250, (last_draw + FRAME_MIN - now) * 1000)) : 250;
        for (int k; (k = tui_screen_key(wait_ms)) != 0; wait_ms = 0) {
            key(a, k);
            keyed = 1;
            if (a->quit) break;
        }
        if (a->quit) break;
        if (a->running) {
            /* step until the next redraw, looking at the keys at least 20 times a second */
            double t0 = tui_wall(), until = fmin(next_draw, t0 + 0.05);
            long s0 = 0;
            if (a->s) {
                hearth_stats st;
                hearth_scene_stats(a->s, &st);
                s0 = st.step;
            }
            do {
                if (tui_step(a)) break;
            } while (tui_wall() < until && !tui_screen_interrupted());
            a->step_secs += tui_wall() - t0;
            if (a->s) {
                hearth_stats st;
                hearth_scene_stats(a->s, &st);
                a->steps_run += st.step - s0;
            }
            dirty = 1;
        }
        now = tui_wall();
        if (now - a->rate_wall >= 0.5 && a->s) { /* steps per second over half-second windows */
            hearth_stats st;
            hearth_scene_stats(a->s, &st);
            a->sps = fmax(0, (double)(st.step - a->rate_step) / (now - a->rate_wall));
            a->rate_step = st.step;
            a->rate_wall = now;
        }
        if (a->log.changed != seen_log) keyed = 1;
        if (now - last_draw < FRAME_MIN) continue; /* 30 redraws a second at most */
        if (a->running ? now >= next_draw : dirty || keyed) {
            /* the full redraw: probes and slices afresh */
            double t0 = tui_wall();
            if (a->running) tui_sample_probes(a);
            tui_view_draw(a, 1);
            double cost = tui_wall() - t0;
            if (a->running) a->draw_secs += cost;
            next_draw = t0 + fmax(FRAME_MIN, cost / DRAW_SHARE);
            last_draw = t0;
            dirty = keyed = 0;
            seen_log = a->log.changed;
        } else if (keyed) {
            /* a key while running: show it now from the last probes, which costs little */
            double t0 = tui_wall();
            tui_view_draw(a, 0);
            if (a->running) a->draw_secs += tui_wall() - t0;
            last_draw = t0;
            keyed = 0;
            seen_log = a->log.changed;
        }
    }
    tui_screen_close();
    if (a->status == 130) fprintf(stderr, "hearth: interrupted\n");
    if (a->steps_run > 0)
        fprintf(stderr, "hearth: %ld steps while running: %.3f s stepping, %.3f s drawing (%.2f%% of the step time)\n",
                a->steps_run, a->step_secs, a->draw_secs, 100 * a->draw_secs / fmax(a->step_secs, 1e-9));
    int st = a->status;
    app_free(a);
    free(a);
    return st;
}
