/* main.c: the hearth command line. Dispatches to subcommands. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"
#include "crash.h"
#include "hearth/hearth.h"
#include "run_log.h"

static void usage(FILE *f) {
    fprintf(f,
            "hearth %s: a terminal workbench for simulating cooking materials\n"
            "\n"
            "usage:\n"
            "  hearth [SCENE.lua] [--out DIR] [--set k=v]... [--until T] [--play] [--trust]\n"
            "                                the live dashboard on a scene, or on the built-in demo; it needs a\n"
            "                                terminal (press ? inside for the keys; hearth --help-dashboard)\n"
            "  hearth demo [--out DIR] [--until T] [--frames N] [--movie FILE] [--threads N] [--quiet]\n"
            "                                the built-in demo headless: progress bar, PNG frames in ./hearth-out/demo/\n"
            "  hearth run SCENE.lua [--until T] [--frames N] [--out DIR] [--set k=v]... [--threads N] [--quiet] [--trust]\n"
            "                     [--vtu DIR] [--movie FILE]  (hearth run --help lists every option)\n"
            "                                run a Lua scene headless (progress bar, PNG/VTU/CSV outputs)\n"
            "  hearth run SCENE.lua --params the scene's parameters (--set), their defaults and words, and stop\n"
            "  hearth repl [SCENE.lua]       a plain Lua prompt with the scene loaded (reads pipes too)\n"
            "  hearth plugins                list material plugins and their parameters\n"
            "  hearth plugin check [--timeout S] FILE.so\n"
            "                                run the conformance battery on one plugin, isolated in a child process\n"
            "  hearth rheometer MATERIAL [--mix sauce.a:0.5,sauce.b:0.5] [--rates MIN:MAX:COUNT] [--out DIR] [--json]\n"
            "                                flow curve of a material or library sauce in a virtual rheometer\n"
            "  hearth fit FLOWCURVE.csv [--json] [--out DIR]\n"
            "                                fit sigma = sigma_y + eta rate^h (relative error, Nagasawa et al. eq. 2)\n"
            "  hearth trade SCENE.lua --metric NAME [--knob name=v1,v2,...]... [--reference finest|analytic:EXPR] [--out DIR] [--jobs N]\n"
            "               [--launcher local|slurm|mpi]   (hearth trade --collect DIR gathers a submitted ladder)\n"
            "                                run a scene over a ladder of settings: cost, error and order of each\n"
            "  hearth bench [--threads N] [--cells N] [--steps N] [--dim 2|3]\n"
            "                                throughput of a standard elastic block, as JSON\n"
            "  mpirun -n N hearth bench --ranks [--weak] [--cells N] [--dim 2|3]\n"
            "                                the block over N MPI ranks: step time, communication share, bytes\n"
            "  hearth scenes                 list the shipped scenes: each one's path and what it shows\n"
            "  hearth help scene             every h.scene{...} setting: unit, default, range, help\n"
            "  hearth doc man|lua            print the generated settings sections of docs/hearth.1, docs/lua.md\n"
            "  hearth --help | --version\n"
            "\n"
            "Plugins are searched in the build's plugin folder, the install folder,\n"
            "$HEARTH_PLUGIN_PATH (colon separated) and the scene's folder.\n",
            HEARTH_VERSION);
}

long app_parse_int(const char *cmd, const char *flag, const char *text, long min, long max) {
    char *end = NULL;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || errno || end == text || *end || v < min || v > max) {
        fprintf(stderr, "hearth %s: %s needs a whole number in [%ld, %ld], got '%s'\n", cmd, flag, min, max, text ? text : "");
        return -1;
    }
    return v;
}

/* Levenshtein distance of a and b, capped: the names compared are short. */
static size_t edit_distance(const char *a, const char *b) {
    size_t la = strlen(a), lb = strlen(b);
    if (la > 63 || lb > 63) return (size_t)-1;
    size_t row[64];
    for (size_t j = 0; j <= lb; j++) row[j] = j;
    for (size_t i = 1; i <= la; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t up = row[j], best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            diag = up;
            row[j] = best;
        }
    }
    return row[lb];
}

const char *app_did_you_mean(const char *word, const char *const *names) {
    /* a third of the word's length, at least one edit: "rn" finds "run", "xyz" finds nothing */
    size_t limit = strlen(word) / 3 > 1 ? strlen(word) / 3 : 1, best = limit + 1;
    const char *pick = NULL;
    for (size_t k = 0; names[k]; k++) {
        size_t d = edit_distance(word, names[k]);
        if (d < best) best = d, pick = names[k];
    }
    return pick;
}

/* Every PNG a command draws names it in PNG's "Source" text: the command line as given and hearth's version, so a
 * run's frame, the demo's, the dashboard's slice, a trade plot or a flow curve copied elsewhere still says what drew
 * it (#18: helper userview5 for hearth run, helper restartkeep for every command, set once here). */
static void png_source(int argc, char **argv) {
    char text[1024];
    size_t n = (size_t)snprintf(text, sizeof text, "hearth");
    for (int i = 1; i < argc && n < sizeof text; i++) n += (size_t)snprintf(text + n, sizeof text - n, " %s", argv[i]);
    if (n < sizeof text)
        snprintf(text + n, sizeof text - n, " (hearth %s, revision %s)", HEARTH_VERSION, run_log_revision());
    hearth_png_set_source(text);
}

int main(int argc, char **argv) {
    /* Idle OpenMP threads should sleep, not spin: on a shared machine a
     * spinning pool is several times slower as soon as another process runs
     * (measured: dam_break.lua 10.0 s spinning against 2.6 s). libgomp reads
     * the policy when it is loaded, before main, so set it and start again. */
    if (!getenv("OMP_WAIT_POLICY")) {
        setenv("OMP_WAIT_POLICY", "passive", 1);
        /* Under valgrind /proc/self/exe is valgrind's tool, which refuses to be
         * started by hand ("You cannot run ... directly"): there carry on with
         * the default policy. valgrind preloads its vgpreload_*.so. */
        const char *pre = getenv("LD_PRELOAD");
        if (!pre || !strstr(pre, "vgpreload"))
            execv("/proc/self/exe", argv); /* returns only on failure: then carry on as we are */
    }
    /* A plugin that crashes or calls exit() inside a callback is named, and the
     * process ends with status 4 (crash.c); other crashes keep their default. */
    crash_install(-1);
    png_source(argc, argv);
    if (argc < 2) return cmd_dashboard(argc, argv);
    const char *c = argv[1];
    if (!strcmp(c, "help") && argc >= 3) return cmd_help(argc - 1, argv + 1); /* hearth help scene */
    if (!strcmp(c, "--help") || !strcmp(c, "-h") || !strcmp(c, "help")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(c, "--help-dashboard")) {
        char *dash[] = {argv[0], "--help", NULL};
        return cmd_dashboard(2, dash);
    }
    if (!strcmp(c, "--version")) {
        printf("hearth %s (material ABI %d)\n", HEARTH_VERSION, HEARTH_MATERIAL_ABI);
        return 0;
    }
    if (!strcmp(c, "demo")) return cmd_demo(argc - 1, argv + 1);
    if (c[0] == '-' && c[1] == '-') return cmd_dashboard(argc, argv); /* `hearth --play`: the dashboard on the demo */
    if (!strcmp(c, "plugins")) return cmd_plugins(argc - 1, argv + 1);
    if (!strcmp(c, "plugin")) {
        if (argc >= 3 && !strcmp(argv[2], "check")) return cmd_plugin_check(argc - 2, argv + 2);
        fprintf(stderr, "hearth plugin: unknown action '%s'; try: hearth plugin check FILE.so\n", argc >= 3 ? argv[2] : "");
        return 2;
    }
    int bench_ranks = 0; /* hearth bench --ranks: the other command that runs over mpirun's ranks */
    for (int i = 2; !strcmp(c, "bench") && i < argc; i++) bench_ranks |= !strcmp(argv[i], "--ranks");
    if (!strcmp(c, "bench") && !bench_ranks) return cmd_bench(argc - 1, argv + 1);
    if (!strcmp(c, "run") || bench_ranks) { /* the commands that run over mpirun's ranks (docs/scaling.md) */
        hearth_ranks_init(&argc, &argv);
        const char *world = getenv("OMPI_COMM_WORLD_SIZE") ? getenv("OMPI_COMM_WORLD_SIZE") : getenv("PMI_SIZE");
        const char *no_ranks = getenv("HEARTH_NO_RANKS");
        if (!hearth_ranks_built() && world && atoi(world) > 1 && !(no_ranks && no_ranks[0] == '1')) { /* N copies would each run the whole scene */
            fprintf(stderr, "hearth %s: started as one of %d MPI ranks, but this hearth was built without MPI; "
                            "rebuild with libopenmpi-dev installed (meson -Dmpi=enabled), or run it without mpirun\n",
                    c, atoi(world));
            return 2;
        }
        const int st = bench_ranks ? cmd_bench(argc - 1, argv + 1) : cmd_run(argc - 1, argv + 1);
        if (st && hearth_ranks_size() > 1) {
            /* A failure on one rank alone (a file rank 0 could not write) leaves the
             * others waiting in the next exchange, where MPI_Finalize would wait for
             * them too. Leaving without it makes mpirun end every rank, with this
             * status. (MPI_Abort did the same but crashed OpenMPI 4.1's mpirun when
             * two ranks called it at once, as a guard stop on every rank does.) */
            fflush(stdout), fflush(stderr);
            _exit(st);
        }
        hearth_ranks_finalize();
        return st;
    }
    if (!strcmp(c, "repl")) return cmd_repl(argc - 1, argv + 1);
    if (!strcmp(c, "rheometer")) return cmd_rheometer(argc - 1, argv + 1);
    if (!strcmp(c, "fit")) return cmd_fit(argc - 1, argv + 1);
    if (!strcmp(c, "trade")) return cmd_trade(argc - 1, argv + 1);
    if (!strcmp(c, "doc")) return cmd_doc(argc - 1, argv + 1);
    if (!strcmp(c, "scenes")) return cmd_scenes(argc - 1, argv + 1);
    if (strlen(c) > 4 && !strcmp(c + strlen(c) - 4, ".lua")) return cmd_dashboard(argc, argv);
    static const char *const commands[] = {"demo", "run", "repl", "plugins", "plugin", "rheometer", "fit", "trade",
                                           "bench", "help", "doc", "scenes", NULL};
    /* `hearth list` and `hearth ls` ask for the scenes by another name (userview4's item 12) */
    const char *near = !strcmp(c, "list") || !strcmp(c, "ls") ? "scenes" : app_did_you_mean(c, commands);
    if (near) {
        fprintf(stderr, "hearth: unknown command '%s'; did you mean '%s'? (hearth --help lists them)\n", c, near);
        return 2;
    }
    fprintf(stderr, "hearth: unknown command '%s'\n\n", c);
    usage(stderr);
    return 2;
}
