/* cmd_dashboard.c: `hearth` and `hearth SCENE.lua`, the live dashboard
 * (app/tui/). This file reads the command line and picks the scene;
 * the dashboard itself is tui_run. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "tui/tui_app.h"

/* The scene `hearth` opens with no scene file: the one place to change it.
 * Today the built-in demo (a jelly disc and syrup falling into a cup); the
 * cookie bake takes its place when its material lands. */
/* The scene `hearth` opens by default: a cookie baking (assets/cookie_bake.lua);
 * without the assets folder, the demo built in C. */
#define BUILTIN_SCENE_FILE "cookie_bake.lua"
static hearth_scene *builtin_scene(const char **name, hearth_error *err) {
    *name = "built-in demo: jelly and syrup into a cup";
    return app_demo_scene(err);
}
#define BUILTIN_OUT "hearth-out/demo"

static void usage(FILE *f) {
    fprintf(f, "usage: hearth [SCENE.lua] [--out DIR] [--set k=v]... [--threads N] [--trust] [--until T]\n"
               "              [--lua-memory SIZE] [--memory SIZE] [--play] [--exit-when-done]\n"
               "The live dashboard: two slice views, status, probes, a log and a Lua prompt.\n"
               "With no scene it opens the built-in demo. Press ? inside for the keys.\n"
               "  --out DIR         where s, c and the scene's outputs go (default hearth-out/<scene>)\n"
               "  --set k=v         override a parameter the scene declares with h.params{...}\n"
               "  --until T         stop every s:run at sim time T (s), with a frame of the state there\n"
               "  --play            start running instead of paused\n"
               "  --exit-when-done  quit when the scene's runs have finished (for benchmarks)\n"
               "  --lua-memory SIZE ceiling of the scene's Lua memory (default 512M)\n"
               "  --memory SIZE     ceiling of the simulation's memory (default half the machine's)\n"
               "  --trust           lift the scene sandbox\n"
               "It needs a terminal; for pipes and scripts use `hearth run SCENE.lua` (headless)\n"
               "or `hearth repl [SCENE.lua]` (a plain prompt). TERM=dumb gives a line mode.\n");
}

int cmd_dashboard(int argc, char **argv) {
    char *args[256];
    int n = 0, play = 0, exit_when_done = 0;
    for (int i = 0; i < argc && n < 255; i++) {
        if (i > 0 && (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))) {
            usage(stdout);
            return 0;
        }
        if (i > 0 && !strcmp(argv[i], "--play")) play = 1;
        else if (i > 0 && !strcmp(argv[i], "--exit-when-done")) exit_when_done = 1;
        else args[n++] = argv[i];
    }
    args[n] = NULL;
    if (!isatty(STDOUT_FILENO)) {
        fprintf(stderr, "hearth: the dashboard needs a terminal, and stdout is not one.\n"
                        "  for a headless run:  hearth run SCENE.lua   (or hearth demo for the built-in scene)\n"
                        "  for a plain prompt:  hearth repl [SCENE.lua]\n");
        return 2;
    }
    /* no scene given: the cookie bake in the assets folder, when it is there */
    int has_scene = 0;
    for (int i = 1; i < n; i++) {
        const size_t l = strlen(args[i]);
        has_scene |= l > 4 && !strcmp(args[i] + l - 4, ".lua");
    }
    static char cookie[4096];
    snprintf(cookie, sizeof cookie, "%s/" BUILTIN_SCENE_FILE, app_assets_dir());
    if (!has_scene && n < 255 && access(cookie, R_OK) == 0) {
        for (int i = n; i >= 1; i--) args[i + 1] = args[i];
        args[1] = cookie;
        n++;
    }
    run_args a;
    int rc = app_run_parse(&a, n, args, "dashboard");
    if (rc) return rc == 1 ? 0 : rc;
    if (!a.scene && a.out == a.out_buf) a.out = BUILTIN_OUT;

    tui_options o = {.scene = a.scene, .play = play, .exit_when_done = exit_when_done};
    hearth_error err;
    if (hearth_mkdir_p(a.out, &err)) {
        fprintf(stderr, "hearth: %s\n", err.msg);
        return 1;
    }
    int stale = hearth_clean_stale_temps(a.out);
    if (stale > 0) fprintf(stderr, "hearth: removed %d stale temporary file%s of killed runs from %s/\n", stale, stale == 1 ? "" : "s", a.out);
    if (a.scene) {
        /* plugins next to the scene load only with --trust: an untrusted scene may have put them there */
        if (a.trust) hearth_plugin_path_add(a.dir_buf);
        o.name = a.scene;
    } else if (!(o.builtin = builtin_scene(&o.name, &err))) {
        fprintf(stderr, "hearth: the built-in scene: %s\n", err.msg);
        return 1;
    }
    a.sets[a.nsets] = NULL;
    o.lua = (hl_options){.out_dir = a.out, .scene_dir = a.dir_buf, .until_override = a.until,
                         .frames_override = (int)a.frames, .quiet = 1, .trusted = a.trust, .sets = a.sets,
                         .assets_dir = app_assets_dir(), .lua_memory = a.lua_memory};
    return tui_run(&o);
}
