/* exp_memo.h: exp through a particle's memo (PC_THERMAL_MEMO, PC_GAS_MEMO).
 *
 * Between two updates of the fields (field_clock.c) the temperature a particle
 * holds does not move, so the exponentials the dough step takes of it every
 * step (the thermal split's scale, the CO2 rate) have the same argument step
 * after step: on the 2D dough bench k = 203 steps a cycle, and one exp is
 * 20-60 instructions. A memo keeps the last argument and its exp, and a step
 * whose argument equals it to the bit reads the value instead of calling exp.
 *
 * It is a cache keyed on the argument's value, not state: exp is a function of
 * its argument (+0 and -0 alike give 1), so a hit is the bits the call would
 * give, whatever wrote the memo and whenever. Nothing has to invalidate it
 * (a field step, a material edit, a rollback, the sort's permutation), and so
 * it is left out of hearth_scene_hash and of checkpoints: a restored scene
 * starts with zeroed memos and fills them. A zeroed entry must miss (exp(0) is
 * 1, not 0): a hit needs a value other than 0, which every finite exp above
 * -745 is; an argument whose exp underflows to 0 (or a NaN) just misses.
 * Rejected: a value invalidated by the field step's clock, which would have
 * to follow every other path that moves a temperature or a parameter (held
 * bodies, temperature curves, Lua edits, restores) to stay the same bits. */
#ifndef HEARTH_EXP_MEMO_H
#define HEARTH_EXP_MEMO_H
#include <math.h>

/// exp(x), through memo m[0] (the last argument) and m[1] (its exp): the same bits as exp(x).
static inline double exp_memo(double *m, double x) {
    if (m[0] == x && m[1] != 0) return m[1];
    const double e = exp(x);
    m[0] = x, m[1] = e;
    return e;
}
#endif
