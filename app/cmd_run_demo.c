/* cmd_run_demo.c: the built-in demo scene, embedded so `hearth` works with no
 * files: a jelly disc and a blob of syrup fall onto a ramp and into a cup.
 * `hearth demo` runs it headless with a progress bar and writes PNG frames
 * (with --movie also a movie of them, through the ffmpeg program) and the run
 * record (run_log.c); the dashboard (cmd_dashboard.c) shows it live. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "hearth_lua.h"
#include "progress.h"
#include "run_log.h"


hearth_scene *app_demo_scene(hearth_error *err) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = 1.0 / 128;
    d.hi[0] = 1.0;
    d.hi[1] = 0.75;
    d.wall = HEARTH_SEPARATE;
    hearth_scene *s = hearth_scene_create(&d, err);
    if (!s) return NULL;
    const char *jn[] = {"E", "nu", "density"};
    const double jv[] = {5e4, 0.3, 1000};
    const char *sn[] = {"bulk", "viscosity", "density"};
    const double sv[] = {2e5, 20.0, 1400}; /* honey-like: about 10-20 Pa s */
    int jelly = hearth_scene_add_material(s, "elastic", jn, jv, 3, err);
    int syrup = jelly < 0 ? -1 : hearth_scene_add_material(s, "newtonian", sn, sv, 3, err);
    if (syrup < 0) goto fail;

    /* a cup at the bottom right and a ramp leading into it from the left */
    const double base[3] = {0.68, 0.045, 0}, up[3] = {0, 1, 0}; /* the cup's floor rests on the oven floor */
    hearth_shape *cup = hearth_shape_container(base, up, 0.2, 0.22, 0.03, 0.03);
    const double rp[3] = {0.25, 0.25, 0}, rn[3] = {0.42, 1.0, 0};
    hearth_shape *plane = hearth_shape_plane(rp, rn);
    const double bc[3] = {0.24, 0.15, 0}, bh[3] = {0.24, 0.15, 0};
    hearth_shape *boxr = hearth_shape_box(bc, bh);
    hearth_shape *ramp = plane && boxr ? hearth_shape_combine(HEARTH_INTERSECT, plane, boxr) : NULL;
    hearth_shape_free(plane);
    hearth_shape_free(boxr);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = cup;
    cd.mode = HEARTH_SEPARATE;
    cd.friction = 0.3;
    int ok = cup && ramp && hearth_scene_add_collider(s, &cd, err) >= 0;
    cd.shape = ramp;
    cd.friction = 0.1;
    ok = ok && hearth_scene_add_collider(s, &cd, err) >= 0;
    hearth_shape_free(cup);
    hearth_shape_free(ramp);
    if (!ok) goto fail;

    const double dc[3] = {0.68, 0.42, 0}, v0[3] = {0, 0, 0};
    hearth_shape *disc = hearth_shape_sphere(dc, 0.085);
    const double fc[3] = {0.16, 0.55, 0}, fh[3] = {0.1, 0.1, 0};
    hearth_shape *blob = hearth_shape_box(fc, fh);
    ok = disc && blob && hearth_scene_seed_shape(s, jelly, disc, 4, 0.5, v0, err) > 0 &&
         hearth_scene_seed_shape(s, syrup, blob, 4, 0.5, NULL, err) > 0;
    hearth_shape_free(disc);
    hearth_shape_free(blob);
    if (ok) return s;
fail:
    hearth_scene_destroy(s);
    return NULL;
}

int cmd_demo(int argc, char **argv) {
    const char *out = "hearth-out/demo", *movie = NULL;
    double until = 1.5;
    long frames = 30;
    int quiet = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help")) {
            printf("usage: hearth [demo] [--out DIR] [--until T] [--frames N] [--movie FILE] [--threads N] [--quiet]\n"
                   "Runs the built-in demo scene (a jelly disc and syrup falling into a cup) headless,\n"
                   "writing PNG frames coloured by speed to DIR (default hearth-out/demo) and the run\n"
                   "record DIR/run.log and DIR/run.json.\n"
                   "  --movie FILE the frames also become the movie FILE (under DIR unless absolute; .mp4,\n"
                   "               10 fps) through the ffmpeg program; without ffmpeg a notice says so and\n"
                   "               the frames stay\n");
            return 0;
        }
        if (i + 1 >= argc && strcmp(a, "--quiet")) {
            fprintf(stderr, "hearth demo: %s needs a value (see --help)\n", a);
            return 2;
        }
        if (!strcmp(a, "--out")) out = argv[++i];
        else if (!strcmp(a, "--movie")) {
            movie = argv[++i];
            const char *base = strrchr(movie, '/'), *dot = strrchr(base ? base : movie, '.');
            if (!dot || !dot[1]) { /* ffmpeg picks the container from it */
                fprintf(stderr, "hearth demo: --movie %s needs an extension naming the container, e.g. demo.mp4\n", movie);
                return 2;
            }
        }
        else if (!strcmp(a, "--until")) {
            char *end;
            until = strtod(argv[++i], &end);
            if (*end || !(until > 0 && until < 1e6)) {
                fprintf(stderr, "hearth demo: --until needs a time in (0, 1e6) s, got '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(a, "--frames")) {
            if ((frames = app_parse_int("demo", "--frames", argv[++i], 1, 100000)) < 0) return 2;
        } else if (!strcmp(a, "--threads")) {
            long t = app_parse_int("demo", "--threads", argv[++i], 1, 1024);
            if (t < 0) return 2;
            hearth_set_threads((int)t);
        } else if (!strcmp(a, "--quiet")) quiet = 1;
        else {
            fprintf(stderr, "hearth demo: unknown option '%s' (see --help)\n", a);
            return 2;
        }
    }
    hearth_error err;
    hearth_scene *s = app_demo_scene(&err);
    if (!s) {
        fprintf(stderr, "hearth demo: %s\n", err.msg);
        return 1;
    }
    if (hearth_mkdir_p(out, &err)) {
        fprintf(stderr, "hearth demo: %s\n", err.msg);
        hearth_scene_destroy(s);
        return 1;
    }
    run_log rec;
    run_log_start(&rec, "demo", argc, argv, NULL, out, NULL, 0);
    if (!quiet)
        fprintf(stderr, "hearth demo: %d particles, writing %ld frames to %s/\n", hearth_scene_particle_count(s), frames, out);
    progress pr;
    progress_start(&pr, until, quiet);
    int status = 0;
    hearth_stats st;
    double held[2] = {0, 1}; /* the speed range the frames so far were drawn with (m/s) */
    for (long f = 0; f <= frames; f++) {
        const double t = until * (double)f / frames;
        hearth_status rc = HEARTH_OK;
        while (rc == HEARTH_OK) {
            hearth_scene_stats(s, &st);
            if (st.t >= t) break;
            /* advance in small pieces so the progress bar moves */
            double next = st.t + until / (frames * 8.0);
            rc = hearth_scene_advance(s, next < t ? next : t, &err);
            hearth_scene_stats(s, &st);
            progress_update(&pr, st.t, st.step);
        }
        if (rc != HEARTH_OK) {
            progress_finish(&pr, st.t, st.step);
            fprintf(stderr, "hearth demo: %s\n", err.msg);
            run_log_message(&rec, err.msg);
            status = rc == HEARTH_ERR_GUARD ? 3 : 1;
            break;
        }
        char path[4200];
        snprintf(path, sizeof path, "%s/frame_%04ld.png", out, f);
        /* the frames share one speed scale: each holds the range drawn so far, widened when a frame exceeds it */
        hearth_picture_def pd = hearth_default_picture_def();
        pd.field = "speed", pd.kind = HEARTH_PICTURE_PARTICLES, pd.width = 800, pd.height = 620;
        if (f > 0) pd.range_mode = HEARTH_RANGE_GROW, pd.range[0] = held[0], pd.range[1] = held[1];
        hearth_picture_info info;
        if (hearth_render(s, &pd, path, &info, &err)) {
            fprintf(stderr, "hearth demo: %s\n", err.msg);
            run_log_message(&rec, err.msg);
            status = 1;
            break;
        }
        held[0] = info.range[0], held[1] = info.range[1];
    }
    if (status == 0) {
        progress_finish(&pr, st.t, st.step);
        if (!quiet)
            fprintf(stderr, "hearth demo: done: t = %.3g s in %ld steps, %.1f s wall; frames in %s/\n", st.t, st.step,
                    progress_wall() - pr.t0_wall, out);
    }
    if (status == 0 && movie) { /* as hearth run --movie: 10 frames a second, the frames stay */
        char in[4200], mpath[8400], msg[9000];
        snprintf(in, sizeof in, "%s/frame_%%04d.png", out);
        if (movie[0] == '/') snprintf(mpath, sizeof mpath, "%s", movie);
        else snprintf(mpath, sizeof mpath, "%s/%s", out, movie);
        char *slash = strrchr(mpath, '/');
        if (slash) { /* a movie in a subfolder of the outputs */
            *slash = '\0';
            int bad = hearth_mkdir_p(mpath, &err);
            *slash = '/';
            if (bad) {
                fprintf(stderr, "hearth demo: %s\n", err.msg);
                run_log_message(&rec, err.msg);
                status = 1;
            }
        }
        int mrc = status ? 0 : hl_movie_encode(in, 0, frames + 1, mpath, 10.0, movie, msg, sizeof msg);
        if (mrc) {
            fprintf(stderr, "hearth demo: %s\n", msg);
            if (mrc < 0) status = 1, run_log_message(&rec, msg);
        } else if (!status && !quiet) fprintf(stderr, "hearth demo: movie %s\n", mpath);
    }
    hearth_scene_stats(s, &st);
    run_log_stats(&rec, &st);
    run_log_write(&rec, status);
    hearth_scene_destroy(s);
    return status;
}
