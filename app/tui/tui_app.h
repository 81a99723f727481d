/* tui_app.h: the dashboard's state, shared by the loop (tui_app.c), the
 * panels (tui_view.c) and the line mode for TERM=dumb (tui_lines.c). */
#ifndef HEARTH_TUI_APP_H
#define HEARTH_TUI_APP_H
#include "hearth/hearth.h"
#include "hearth_lua.h"
#include "tui_draw.h"
#include "tui_log.h"
#include "tui_lua.h"
#include "tui_prompt.h"

#define TUI_HIST 64       ///< sparkline history length (redraws)
#define TUI_MAX_FIELDS 24
#define TUI_MAX_PINS 4

/// How the dashboard was asked to start (from the command line).
typedef struct tui_options {
    const char *scene;     ///< scene file, or NULL for the built-in scene
    hearth_scene *builtin; ///< the built-in scene when scene is NULL (taken over)
    const char *name;      ///< shown in the status bar
    hl_options lua;        ///< module options (out_dir, sets, trust, until)
    int play;              ///< start running (--play)
    int exit_when_done;    ///< quit when the scene's runs have finished (--exit-when-done)
} tui_options;

typedef struct tui_field_probe {
    char name[32];
    double hist[TUI_HIST];
    int n;
    double value;
} tui_field_probe;

/// What a view's slice buffer holds, so a redraw can tell whether it still fits.
typedef struct tui_probed {
    char field[32];
    int axis, zoom, fw, fh, valid;
    double at;
} tui_probed;

typedef struct tui_app {
    tui_options opt;
    tui_color_mode mode;
    tui_lua lua;
    tui_log log;
    tui_prompt prompt;
    hearth_scene *s;
    int running, prompt_focus, help, ask_quit, quit, status;
    int unsaved;       ///< changed since the last checkpoint
    char field[2][32]; ///< the views' fields
    int axis;          ///< slice axis 0, 1, 2 (2 in 2D)
    double at[3];      ///< slice position along each axis, as a fraction of the domain
    int zoom;          ///< 1, 2, 4, 8
    double cursor[3];  ///< probe cursor (m)
    tui_field_probe fp[TUI_MAX_FIELDS];
    int nfp;
    int probe_first;   ///< the first field the probe panel shows (PgUp / PgDn scroll it)
    int probe_page;    ///< fields the panel showed at the last draw (a PgDn's step)
    double pin[TUI_MAX_PINS][3];
    tui_field_probe pin_probe[TUI_MAX_PINS];
    int npins;
    double sampled_t;  ///< sim time of the last probe sample
    long sampled_step;
    char chunk[8192];  ///< a multi-line statement being typed
    /* timing */
    double step_secs, draw_secs, sps, rate_wall;
    long rate_step, steps_run;
    /* scratch */
    double *slice[2];  ///< each view's last slice, reused by redraws between probes
    long slice_cap[2];
    tui_probed probed[2]; ///< what slice[k] holds
    tui_cell *cells;
    long cells_cap;
    double lo[2], hi[2];
} tui_app;

/// Run the dashboard. Returns the exit status (0 quit, 130 interrupted, 1 failed to start).
int tui_run(const tui_options *o);

/* between the dashboard's files */
void tui_view_draw(tui_app *a, int fresh);           /* tui_view.c: the whole screen; fresh = probe the slices
                                                        again (else reuse them when the view is unchanged) */
void tui_sample_probes(tui_app *a);                  /* tui_view.c: cursor and pinned probes */
void tui_default_fields(tui_app *a);                 /* tui_view.c: choose live fields for the views */
int tui_scalar_fields(const hearth_scene *s, char out[][32], int max); /* live scalar fields */
int tui_step(tui_app *a);                            /* tui_app.c: one step (a job's or a plain one); 0 = keep going */
void tui_status_line(tui_app *a, char *buf, unsigned long n); /* tui_view.c: one-line summary */
int tui_lines_run(tui_app *a);                       /* tui_lines.c: TERM=dumb */
double tui_wall(void);
#endif
