/* solver.c: the table of solvers (solver.h) and the one check every solver
 * shares, that it fills each point field a material needs. */
#include "solver.h"

#include "error.h"

const solver *solver_of(int kind) {
    static const solver *const table[] = {[HEARTH_SOLVER_MPM] = &mpm_solver, [HEARTH_SOLVER_SPH] = &sph_solver};
    return kind >= 0 && kind < (int)(sizeof table / sizeof table[0]) ? table[kind] : NULL;
}

hearth_status solver_accepts(const solver *sv, const hearth_material *m, hearth_error *err) {
    static const struct {
        unsigned bit;
        const char *field, *bit_name;
    } fields[] = {{HEARTH_NEEDS_TEMPERATURE, "temperature", "TEMPERATURE"},
                  {HEARTH_NEEDS_POROSITY, "porosity", "POROSITY"},
                  {HEARTH_NEEDS_SATURATION, "saturation", "SATURATION"}};
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++) {
        if (!(m->needs & fields[k].bit) || (sv->supplies & fields[k].bit)) continue;
        const solver *other = sv != &mpm_solver && (mpm_solver.supplies & fields[k].bit) ? &mpm_solver : NULL;
        return err_set(err, HEARTH_ERR_PARAM,
                       "material '%s' needs the point's %s (HEARTH_NEEDS_%s), which the %s solver does not supply%s%s%s",
                       m->name, fields[k].field, fields[k].bit_name, sv->name, other ? "; solver = \"" : "",
                       other ? other->name : "", other ? "\" does" : "");
    }
    return HEARTH_OK;
}
