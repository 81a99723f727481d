/* colormap.c: viridis, inferno, cividis, cool-warm, the crust's browning and
 * grey as piecewise-linear maps.
 *
 * The anchors are the published matplotlib colour maps (van der Walt and
 * Smith, 2015) sampled at t = k/16, k = 0..16, and rounded to 8 bits.
 * Seventeen anchors with linear interpolation in sRGB stay within about 6/255
 * per channel of the full 256-entry tables, which is below what a frame
 * needs; the full tables were rejected as 1.5 kB of numbers that buy nothing
 * visible. Interpolating in sRGB rather than linear light keeps the
 * lightness ramp of the originals, which were designed in sRGB steps.
 * Cividis (Nunez et al. 2018) reads the same to the common colour-vision
 * deficiencies. The diverging map is Moreland's (2009) cool-warm: blue through
 * a light grey to red, its lightness rising to the middle and falling again
 * symmetrically, for signed fields (a velocity or stress component) around 0;
 * blue-white-red with a white middle was rejected because its lightness
 * jumps at the ends. */
#include "colormap.h"

#include <math.h>
#include <string.h>

#include "error.h"

#define N_ANCHORS 17

static const unsigned char viridis[N_ANCHORS][3] = {
    {68, 1, 84},    {72, 24, 106},  {71, 45, 123},   {66, 64, 134},   {59, 82, 139},
    {51, 99, 141},  {44, 114, 142}, {38, 129, 142},  {33, 144, 140},  {31, 159, 136},
    {40, 174, 128}, {62, 188, 116}, {93, 201, 99},   {130, 211, 76},  {171, 220, 50},
    {213, 226, 26}, {253, 231, 37},
};

static const unsigned char inferno[N_ANCHORS][3] = {
    {0, 0, 4},      {11, 7, 36},    {33, 12, 74},    {60, 9, 101},    {87, 16, 109},
    {112, 25, 110}, {137, 34, 106}, {163, 43, 97},   {187, 55, 85},   {209, 70, 68},
    {227, 89, 50},  {241, 113, 30}, {249, 141, 10},  {252, 171, 15},  {249, 202, 50},
    {242, 232, 101}, {252, 255, 164},
};

static const unsigned char cividis[N_ANCHORS][3] = {
    {0, 34, 78},     {0, 46, 106},    {26, 56, 111},   {50, 67, 109},   {67, 78, 108},
    {83, 90, 109},   {97, 101, 111},  {111, 112, 115}, {125, 124, 120}, {140, 136, 120},
    {155, 148, 118}, {171, 160, 114}, {188, 174, 108}, {205, 187, 99},  {222, 201, 88},
    {240, 216, 70},  {254, 232, 56},
};

static const unsigned char coolwarm[N_ANCHORS][3] = {
    {59, 76, 192},   {78, 104, 216},  {98, 130, 234},  {119, 154, 247}, {141, 176, 254},
    {163, 194, 254}, {185, 208, 249}, {204, 217, 237}, {221, 220, 220}, {236, 211, 197},
    {245, 196, 172}, {247, 176, 147}, {244, 152, 122}, {235, 125, 98},  {221, 95, 75},
    {202, 59, 55},   {180, 4, 38},
};

/* Crust colour for the browning index (fields/browning.c; Rodriguez-Arenas 2011 §4.4 maps
 * it through a texture gradient): raw dough, golden, deep brown. Our own
 * anchors, interpolated like the others. */
static const unsigned char browning[N_ANCHORS][3] = {
    {242, 226, 190}, {240, 220, 178}, {238, 212, 164}, {236, 203, 148}, {233, 193, 131},
    {229, 181, 113}, {224, 168, 96},  {217, 154, 80},  {208, 139, 66},  {197, 124, 54},
    {184, 109, 44},  {168, 95, 37},   {151, 82, 31},   {133, 69, 27},   {114, 58, 24},
    {95, 48, 21},    {76, 38, 18},
};

static unsigned char to_byte(double v) {
    /* v is already within 0..255; the + 0.5 rounds to nearest. */
    return (unsigned char)(v + 0.5);
}

void cmap_eval(int map, double t, unsigned char rgb[3]) {
    if (isnan(t)) {
        rgb[0] = rgb[1] = rgb[2] = CMAP_NAN_GREY;
        return;
    }
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;

    const unsigned char(*table)[3] = NULL;
    switch (map) {
    case CMAP_VIRIDIS: table = viridis; break;
    case CMAP_INFERNO: table = inferno; break;
    case CMAP_BROWNING: table = browning; break;
    case CMAP_CIVIDIS: table = cividis; break;
    case CMAP_COOLWARM: table = coolwarm; break;
    case CMAP_GRAY: rgb[0] = rgb[1] = rgb[2] = to_byte(255.0 * t); return;
    default:
        HEARTH_ASSERT(!"unknown colour map");
        rgb[0] = rgb[1] = rgb[2] = to_byte(255.0 * t); /* release builds: grey */
        return;
    }

    double s = t * (N_ANCHORS - 1);
    int k = (int)s;
    if (k > N_ANCHORS - 2) k = N_ANCHORS - 2; /* t == 1 uses the last segment's end */
    double f = s - k;
    for (int c = 0; c < 3; c++) rgb[c] = to_byte((1.0 - f) * table[k][c] + f * table[k + 1][c]);
}

static const struct {
    const char *name;
    int id;
} names[] = {{"viridis", CMAP_VIRIDIS},   {"inferno", CMAP_INFERNO},   {"cividis", CMAP_CIVIDIS}, {"coolwarm", CMAP_COOLWARM},
             {"browning", CMAP_BROWNING}, {"gray", CMAP_GRAY},         {"diverging", CMAP_COOLWARM}};

int cmap_by_name(const char *name) {
    if (!name) return -1;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(name, names[i].name) == 0) return names[i].id;
    return -1;
}

const char *cmap_name(int map) {
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (names[i].id == map) return names[i].name;
    return "?";
}

const char *cmap_names(void) { return "viridis, inferno, cividis, coolwarm (or diverging), browning, gray"; }
