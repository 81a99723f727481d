/* params.c: parameter validation with messages that say how to fix the input. */
#include "params.h"

#include <math.h>
#include <string.h>

#include "error.h"

/* Ding et al. 2019 eq. 9 (kappa, alpha, c lambda) and eq. 10 (thermal stress). */
static const hearth_param core_schema[CP_COUNT] = {
    [CP_CONDUCTIVITY] = {"conductivity", "W/(m K)", "heat conduction kappa (Ding et al. eq. 9)", 0.5, 0, 1e4},
    [CP_SPECIFIC_HEAT] = {"specific_heat", "J/(kg K)", "specific heat alpha (Ding et al. eq. 9)", 2500, 1, 1e7},
    [CP_EXPANSION] = {"expansion", "Pa/K", "thermal expansion coupling c lambda (Ding et al. eq. 9-10); 0 = none", 0, 0, 1e9},
    [CP_REFERENCE_T] = {"reference_temperature", "degC", "temperature of zero thermal stress", 20, -273.15, 5000},
    [CP_GAS_RATE] = {"gas_rate", "mol/(kg s)", "leavening CO2 rate alpha^g (Ding et al. §5.4); 0 = no gas", 0, 0, 1e3},
    [CP_REACTION_T] = {"reaction_temperature", "degC", "temperature of the peak CO2 rate theta_r", 40, -273.15, 1000},
    [CP_REACTION_WIDTH] = {"reaction_width", "K", "width dtheta of the CO2 rate's bell curve", 20, 1e-3, 1000},
    [CP_POROSITY0] = {"porosity", "1", "initial gas porosity n^p_0 (gas volume over solid-gas volume)", 0.1, 1e-6, 0.99},
    [CP_SATURATION0] = {"saturation", "1", "initial water saturation s_0 = V^w/V, where water is live (Ding et al. §3.2)", 0.5, 0, 1},
    [CP_WATER_DIFFUSIVITY] = {"water_diffusivity", "m^2/(s K)",
                              "Fick's law q^w = -K theta rho^w grad s, theta absolute (Ding et al. §3.2); 0 = water does not move", 0, 0, 1},
    [CP_EVAPORATION] = {"evaporation", "kg/(m^2 s K)",
                        "surface water loss q^w.n = beta^w theta s, theta absolute (Ding et al. §3.2); 0 = none", 0, 0, 10},
    [CP_WATER_STIFFNESS] = {"water_stiffness", "Pa", "water pressure sigma^w = -c (s - s_0) I (Ding et al. eq. 14); 0 = none", 0, 0, 1e9},
    [CP_WATER_DENSITY] = {"water_density", "kg/m^3", "density of pure water rho_0^w (Ding et al. eq. 8)", 1000, 1, 1e5},
    /* Rodriguez-Arenas 2011 eq. 3.50: V_b0 of bubble particles; the SPH solver only */
    [CP_BUBBLE] = {"bubble", "1", "SPH: initial bubble volume V_b0 (eq. 3.50) marks bubble particles; 0 = dough", 0, 0, 100},
    /* a dried crust conducts less than wet crumb (issue #18); material_conductivity, material.h */
    [CP_DRY_CONDUCTIVITY] = {"dry_conductivity", "W/(m K)",
                             "kappa of the dried material: linear in the water left m^w/m^w_0 from it (dry) to conductivity "
                             "(as mixed); at most conductivity; 0 = as wet; SPH scales sph.heat_int by kappa / conductivity",
                             0, 0, 1e4},
    /* the water a dried crust lost took its heat capacity with it (issue #18); material_specific_heat, material.h */
    [CP_DRY_SPECIFIC_HEAT] = {"dry_specific_heat", "J/(kg K)",
                              "alpha of the dried material per kg of the particle's initial mass: linear in the water "
                              "left m^w/m^w_0 from it (dry) to specific_heat (as mixed); at most specific_heat; 0 = as wet",
                              0, 0, 1e7},
    /* eq. 13 as an overpressure over the atmosphere, the pores' gas at p_a to start (gas.h, gas_tau_ambient; #18) */
    [CP_AMBIENT_PRESSURE] = {"ambient_pressure", "Pa",
                             "MPM: eq. 13 as the gauge pressure n R theta / V_pores + p_v - p_a of pores that start "
                             "with air (and vapour) at p_a = this; 0 = eq. 13 as printed (the whole gas's pressure)",
                             0, 0, 1e7},
    [CP_OPEN_TEMPERATURE] = {"open_temperature", "degC",
                             "with ambient_pressure: the temperature at which the pores open to the air (the set crumb "
                             "turns from a foam to a sponge): no gas pressure from there on; 5000 = never",
                             5000, -273.15, 5000},
    /* a leavener of two reactions (issue #18: the sugar-snap cookie's NH4Cl share and its leftover soda, each with
     * its own temperature; gas.c) */
    [CP_GAS_RATE_2] = {"gas_rate_2", "mol/(kg s)",
                       "a second CO2 share's peak rate: eq. 14's bell again, added to gas_rate's, with its own "
                       "reaction_temperature_2 and reaction_width_2; needs gas_rate > 0; 0 = no second share",
                       0, 0, 1e3},
    [CP_REACTION_T_2] = {"reaction_temperature_2", "degC", "temperature of the second CO2 share's peak rate", 40, -273.15,
                         1000},
    [CP_REACTION_WIDTH_2] = {"reaction_width_2", "K", "width of the second CO2 share's bell curve", 20, 1e-3, 1000},
    /* a leavener is a finite amount (issue #18: eq. 14's bell never runs out; gas.h's gas_share_capped) */
    [CP_GAS_AMOUNT] = {"gas_amount", "mol/kg",
                       "the most CO2 gas_rate's share makes (its reactant's moles per kg of dough): its rate stops "
                       "there; needs gas_rate > 0; 0 = no limit (eq. 14 as printed)",
                       0, 0, 1e3},
    [CP_GAS_AMOUNT_2] = {"gas_amount_2", "mol/kg",
                         "the most CO2 the second share (gas_rate_2) makes: its rate stops there; needs gas_rate_2 > 0; "
                         "0 = no limit",
                         0, 0, 1e3},
};

const hearth_param *hearth_core_params(int *n) {
    if (n) *n = CP_COUNT;
    return core_schema;
}

int params_index(const hearth_material *m, const char *name) {
    for (int i = 0; i < m->nparams; i++)
        if (strcmp(m->params[i].name, name) == 0) return i;
    return -1;
}

static int edit_distance(const char *a, const char *b) {
    int la = (int)strlen(a), lb = (int)strlen(b);
    if (la > 63 || lb > 63) return 99;
    int prev[64], cur[64];
    for (int j = 0; j <= lb; j++) prev[j] = j;
    for (int i = 1; i <= la; i++) {
        cur[0] = i;
        for (int j = 1; j <= lb; j++) {
            int sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            int del = prev[j] + 1, ins = cur[j - 1] + 1;
            cur[j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
        }
        memcpy(prev, cur, sizeof(int) * (size_t)(lb + 1));
    }
    return prev[lb];
}

const char *params_nearest(const char *word, const char *const *candidates, int n) {
    const char *best = NULL;
    int bd = 1 << 30;
    for (int i = 0; i < n; i++) {
        int d = edit_distance(word, candidates[i]);
        if (d < bd) {
            bd = d;
            best = candidates[i];
        }
    }
    /* a suggestion further than half the word away is noise */
    return bd <= 1 + (int)strlen(word) / 2 ? best : NULL;
}

hearth_status params_resolve(const hearth_material *m, const char *const *names, const double *values, int n,
                             double *out, double *core, hearth_error *err) {
    for (int i = 0; i < m->nparams; i++) out[i] = m->params[i].def;
    for (int i = 0; i < CP_COUNT; i++) core[i] = core_schema[i].def;
    for (int k = 0; k < n; k++) {
        int i = params_index(m, names[k]), c = -1;
        for (int j = 0; i < 0 && j < CP_COUNT; j++)
            if (strcmp(core_schema[j].name, names[k]) == 0) c = j;
        if (i < 0 && c < 0) {
            const char *cand[64 + CP_COUNT];
            int nc = m->nparams < 64 ? m->nparams : 64;
            for (int j = 0; j < nc; j++) cand[j] = m->params[j].name;
            for (int j = 0; j < CP_COUNT; j++) cand[nc++] = core_schema[j].name;
            const char *near = params_nearest(names[k], cand, nc);
            char list[768] = "";
            for (int j = 0; j < nc; j++) {
                strncat(list, cand[j], sizeof list - strlen(list) - 3);
                if (j + 1 < nc) strncat(list, ", ", sizeof list - strlen(list) - 1);
            }
            if (near)
                return err_set(err, HEARTH_ERR_PARAM, "material '%s': unknown parameter '%s'; did you mean '%s'? (valid: %s)",
                               m->name, names[k], near, list);
            return err_set(err, HEARTH_ERR_PARAM, "material '%s': unknown parameter '%s' (valid: %s)", m->name, names[k], list);
        }
        const hearth_param *p = i >= 0 ? &m->params[i] : &core_schema[c];
        if (!isfinite(values[k]) || values[k] < p->min || values[k] > p->max)
            return err_set(err, HEARTH_ERR_PARAM, "material '%s': parameter '%s' = %g is outside its range [%g, %g] %s (%s)",
                           m->name, p->name, values[k], p->min, p->max,
                           strcmp(p->unit, "1") ? p->unit : "(dimensionless)", p->help);
        if (i >= 0) out[i] = values[k];
        else core[c] = values[k];
    }
    return HEARTH_OK;
}
