/* colormap.h: scalar field -> colour for frames and colour bars. */
#ifndef HEARTH_SIM_COLORMAP_H
#define HEARTH_SIM_COLORMAP_H

/// Colour maps known to cmap_eval. Values are stable (saved in settings).
enum { CMAP_VIRIDIS = 0, CMAP_INFERNO = 1, CMAP_GRAY = 2, CMAP_BROWNING = 3, CMAP_CIVIDIS = 4, CMAP_COOLWARM = 5, CMAP_COUNT };

/// NaN maps to the neutral grey (CMAP_NAN_GREY, CMAP_NAN_GREY, CMAP_NAN_GREY),
/// dark enough to read as "no data" next to every map's low end.
#define CMAP_NAN_GREY 40

/// Colour of t in map (one of the CMAP_ values) as 8-bit sRGB. t is clamped to
/// [0, 1] (so +-inf give the end colours); NaN gives the background grey.
void cmap_eval(int map, double t, unsigned char rgb[3]);

/// Map id for "viridis", "inferno", "cividis", "coolwarm" (alias "diverging"),
/// "browning" or "gray" (exact, lower case); -1 otherwise or for NULL.
int cmap_by_name(const char *name);
/// The map's name ("viridis", ...); "?" for an unknown id.
const char *cmap_name(int map);
/// Every name cmap_by_name knows, for messages: "viridis, inferno, ...".
const char *cmap_names(void);
#endif
