/* top_reference.c: a fine 1D finite-volume reference for the physical loaf's top
 * (docs/validation.md, "The top's reference from the loaf's start"; helper topref).
 *
 * A column from the top face (y = 0, the oven's air) down to an insulated
 * (symmetry) depth H, starting at T0 and the dough's saturation s0. The physics
 * is hearth's as the code and the presets define it, in real time: the preset
 * multiplies every rate (kappa, beta, K, beta^w, browning's k) by S = 300 and
 * runs 1/S of the time, and keeps every capacity (rho c, s, L), so dividing
 * eq. 9 and eq. 22 by S gives this history in t_real = S t
 * (lua/hearth/dough_physical.lua's header). Every number, with where it is read:
 *   rho 484 kg/m^3, c 2700 (wet) and 907.5 (dry) J/(kg K), kappa 0.51 (wet) and
 *   0.23 (dry) W/(m K), s0 0.218, D = 2e-9 m^2/s at 373.15 K and s0, beta^w
 *   1.2e-5: dough_physical.lua's bread; oven 200 degC, beta 30 W/(m^2 K),
 *   dough 25 degC, boiling point 100 degC, 1500 s: the same file's oven;
 *   L = 2.26e6 J/kg (hearth.h HEARTH_LATENT_HEAT), rho_0^w = 1000 kg/m^3 (Ding
 *   et al. eq. 8's water density, the core's default), s_amb = 0 (the scene's
 *   oven.saturation default, settings.c).
 * Per cell: temperature T and saturation s (moisture ratio X = s / s0).
 *   heat  C(X) dT/dt = d/dy (k(X) dT/dy) (Ding et al. eq. 9 without its
 *         expansion term), C = rho (c_d + (c_w - c_d) X) (material.h
 *         material_specific_heat_of: not clamped, floored at 0), k = k_d +
 *         (k_w - k_d) clamp(X, 0, 1) (material_conductivity); the water's own
 *         sensible heat flux c_w q^w . grad T is left out, as hearth leaves it;
 *         harmonic mean of k at the faces.
 *   water d(rho0 s)/dt = -d/dy q^w, q^w = -rho0 K theta s ds/dy (Ding et al.
 *         eq. 22, D = K theta s, theta absolute: transport.c), written as
 *         -rho0 K theta d(s^2/2)/dy at a face (theta the two cells' mean).
 *   boiling: a cell past T_b boils its excess C (T - T_b) / L per volume down
 *         to the floor s = 1e-4 (water.h WATER_SATURATION_FLOOR), T falling by
 *         L / C (C the capacity it was heated with) per kg: water.c water_boil.
 *   top face: the oven's Robin flux beta (T_o - T_f) (or h_c (T_o - T_f) +
 *         eps sigma (T_w^4 - T_f^4) with -r) = conduction into the first cell
 *         + L j, j the evaporation at the face: j = beta^w theta_f (s_f - s_amb)
 *         f(theta_f) (Ding et al. §3.2's flux times water.h's vapour factor f =
 *         min(1, P_sat(theta) / P_sat(T_b)), Clausius-Clapeyron, thesis eq. 2.43
 *         as vapour.h: Delta H_v 40.66 kJ/mol through 101325 Pa at 373.15 K).
 *         s_f closes the half cell's Fick flux as water.h's
 *         water_surface_excess does (s^2 linear over it, a = (h/2) beta^w f /
 *         (rho0 K)); with K = 0, s_f is the first cell's (water.h: a = 0). T_f
 *         solves the face's balance by bisection (its residual falls with T_f).
 *         hearth takes the evaporation's L from the particle beside the face
 *         (transport.c) and its theta there; at h -> 0 the same limit.
 *   browning: browning.c's k0 exp(-Ea / (R theta)) (Zanoni et al. 1995: 42000
 *         1/s, 64151 J/mol) times 1 - s/s0 clamped to [0, 1], at the face with
 *         (T_f, s_f), integrated exactly over each step as browning_advance.
 * Explicit steps of 0.2 h^2 rho c_d / k_w (the heat's limit with margin).
 *
 *   cc -O2 -o top_reference top_reference.c -lm
 *   ./top_reference [h=0.05] [T0=25] [evap=1] [diff=1] [vf=1] [To=200] [beta=30]
 *                   [H=36] [tend=1500] [rad=0 hc=10 eps=0.9 Tw=200] [every=60] [quiet=0]
 *                   [tray=0 betap=100 Tp=200] [yc=-1] [hold=FILE] [cd=907.5] [geo=0] [bw=1.2e-5] [dw=2e-9]
 * h and H in mm; evap 0 sets beta^w = 0, diff 0 sets K = 0, vf 0 drops the
 * vapour factor (eq. 8's flux verbatim); bw sets beta^w (kg/(m^2 s K)) and dw
 * the water diffusivity D at 373.15 K and s0 (m^2/s), for what-ifs; tray=1 puts the bottom face on the
 * loaf's tray (h.recipes.tray: 200 degC through 100 W/(m^2 K) of contact, the
 * oven preset's pan) instead of the symmetry plane, for a column as tall as the
 * loaf; yc prints T at that depth (mm); hold=FILE holds the bottom cell at a
 * temperature history read from FILE ("t_min T" lines: the loaf's centre from
 * its CSV, a diagnostic of the loaf's 2D heating, not an independent
 * reference); geo=1 makes the column a cylinder of radius H heated all round (geo=2 a ball)
 * (the loaf's round top, radius w/2 = 40 mm: lua/hearth/shapes.lua's loaf;
 * the water and boiled totals are then per unit of the outer area). Prints a row per `every` seconds:
 * t (min), face T, s, b; T and s at depths y = 1.25, 0.625, 0.3125 mm (the top
 * particle of a 5, 2.5, 1.25 mm lattice, dx/4 below the face: cell centres
 * interpolated, the face's value above the first centre); water boiled and
 * evaporated (mm of s0 water: kg/m^2 / (1000 s0)); depth of X = 0.5. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double RHO = 484, CW = 2700, CD = 907.5, KW = 0.51, KD = 0.23, S0 = 0.218, TB = 100, LAT = 2.26e6, RHO0 = 1000,
              SAMB = 0, BW = 1.2e-5, DREF = 2e-9, FLOOR = 1e-4, KELV = 273.15, RGAS = 8.314462618, DHV = 40660.0,
              SIGMA = 5.670374419e-8;
static double To = 200, BETA = 30, HC = 10, EPS = 0.9, TW = 200, KWAT; /* K of eq. 22 */
static int RAD = 0, VF = 1;
static double TP = 200, BETAP = 0; /* tray=1: the bottom face on the tray (Robin, no evaporation), else insulated */

/* hold=FILE: the column's bottom cell follows a temperature history (lines "t_min T", at most 256), a
 * diagnostic only: the loaf's crumb as the model heats it from every side, which a 1D column cannot */
static double HT[256], HV[256];
static int NH = 0;
static double held_T(double t) {
    const double m = t / 60;
    if (m <= HT[0]) return HV[0];
    for (int k = 1; k < NH; k++)
        if (m <= HT[k]) return HV[k - 1] + (HV[k] - HV[k - 1]) * (m - HT[k - 1]) / (HT[k] - HT[k - 1]);
    return HV[NH - 1];
}

static double kbr(double T) { return 42000 * exp(-64151 / (RGAS * (T + KELV))); }
static double bfac(double s) { const double f = 1 - s / S0; return f < 0 ? 0 : f > 1 ? 1 : f; }
static double vfac(double th) {
    if (!VF) return 1;
    const double f = exp(-(DHV / RGAS) * (1 / th - 1 / (TB + KELV)));
    return f < 1 ? f : 1;
}
static double kof(double X) { X = X < 0 ? 0 : X > 1 ? 1 : X; return KD + (KW - KD) * X; }
static double cof(double X) { return RHO * (CD + (CW - CD) * (X > 0 ? X : 0)); }
static double qin(double Tf) {
    if (!RAD) return BETA * (To - Tf);
    const double a = TW + KELV, b = Tf + KELV;
    return HC * (To - Tf) + EPS * SIGMA * (a * a * a * a - b * b * b * b);
}
/* the face's saturation and evaporation (kg/(m^2 s)) at face temperature Tf, first cell s_c, half cell hh */
static double face_water(double Tf, double sc, double hh, double *sf) {
    const double th = Tf + KELV, f = vfac(th);
    double s = sc;
    if (BW > 0 && KWAT > 0) { /* water.h water_surface_excess with a = hh beta^w f / (rho0 K) */
        const double a = hh * BW * f / (RHO0 * KWAT), den = sqrt(a * a + sc * sc + 2 * a * SAMB) + a + SAMB;
        s = SAMB + (den > 0 ? (sc - SAMB) * (sc + SAMB) / den : 0);
    }
    *sf = s;
    return BW * th * (s - SAMB) * f;
}

static double arg(int argc, char **argv, const char *k, double d) {
    const size_t n = strlen(k);
    for (int i = argc - 1; i >= 1; i--) /* the last one given wins */
        if (!strncmp(argv[i], k, n) && argv[i][n] == '=') return atof(argv[i] + n + 1);
    return d;
}

int main(int argc, char **argv) {
    const double h = arg(argc, argv, "h", 0.05) * 1e-3, T0 = arg(argc, argv, "T0", 25), H = arg(argc, argv, "H", 36) * 1e-3;
    const double tend = arg(argc, argv, "tend", 1500), every = arg(argc, argv, "every", 60);
    const int quiet = (int)arg(argc, argv, "quiet", 0);
    BW = arg(argc, argv, "bw", BW), DREF = arg(argc, argv, "dw", DREF); /* what-ifs: beta^w, D (helper crustdry) */
    if (!(int)arg(argc, argv, "evap", 1)) BW = 0;
    KWAT = (int)arg(argc, argv, "diff", 1) ? DREF / ((TB + KELV) * S0) : 0;
    VF = (int)arg(argc, argv, "vf", 1);
    CD = arg(argc, argv, "cd", CD); /* cd=2700: the dried crust at the wet c, as the Stefan form takes it */
    To = arg(argc, argv, "To", 200), BETA = arg(argc, argv, "beta", 30);
    RAD = (int)arg(argc, argv, "rad", 0), HC = arg(argc, argv, "hc", 10), EPS = arg(argc, argv, "eps", 0.9);
    TW = arg(argc, argv, "Tw", To);
    BETAP = arg(argc, argv, "tray", 0) ? arg(argc, argv, "betap", 100) : 0, TP = arg(argc, argv, "Tp", 200);
    const double yc = arg(argc, argv, "yc", -1) * 1e-3; /* a depth whose T is printed (the loaf's centre) */
    for (int i = 1; i < argc; i++)
        if (!strncmp(argv[i], "hold=", 5)) {
            FILE *fp = fopen(argv[i] + 5, "r");
            if (!fp) { fprintf(stderr, "hold: cannot open %s\n", argv[i] + 5); return 1; }
            while (NH < 256 && fscanf(fp, "%lf %lf", &HT[NH], &HV[NH]) == 2) NH++;
            fclose(fp);
        }
    const int n = (int)lround(H / h), geo = (int)arg(argc, argv, "geo", 0); /* 1: a cylinder, 2: a ball of radius H */
    double *A = malloc(sizeof(double) * (n + 1)), *Vc = malloc(sizeof(double) * n); /* face areas, cell volumes per h */
    for (int i = 0; i <= n; i++) A[i] = pow((H - i * h) / H, geo);
    for (int i = 0; i < n; i++) { /* the shell's volume over h times the outer area */
        const double ro = (H - i * h) / H, ri = (H - (i + 1) * h) / H;
        Vc[i] = geo ? (pow(ro, geo + 1) - pow(ri, geo + 1)) / ((geo + 1) * h / H) : 1;
    }
    double *T = malloc(sizeof(double) * n), *s = malloc(sizeof(double) * n), *qh = malloc(sizeof(double) * (n + 1)),
           *qw = malloc(sizeof(double) * (n + 1));
    for (int i = 0; i < n; i++) T[i] = T0, s[i] = S0;
    const long nst = (long)ceil(tend / (0.2 * h * h * RHO * CD / KW));
    const double dt = tend / nst, ys[3] = {1.25e-3, 0.625e-3, 0.3125e-3};
    const long per = (long)lround(every / dt);
    double bf = 0, boiled = 0, evap = 0, Tf = T0, sf = S0, t100 = -1, tdry = -1;
    if (!quiet)
        printf("# h %g mm, T0 %g, H %g mm, beta^w %g, K %g, vf %d, To %g, %s %g%s, dt %.3g s\n"
               "# t_min  T_f  s_f  b_f  | T,s at y 1.25 / 0.625 / 0.3125 mm | boiled_mm evap_mm | X=0.5 depth mm\n",
               h * 1e3, T0, H * 1e3, BW, KWAT, VF, To, RAD ? "hc" : "beta", RAD ? HC : BETA, RAD ? " + radiation" : "", dt);
    for (long st = 0; st < nst; st++) {
        /* the face: bisection on beta (To - Tf) - 2 k0 / h (Tf - T0) - L j(Tf), which falls with Tf */
        const double k0 = kof(s[0] / S0), g0 = 2 * k0 / h;
        double lo = -100, hi = (To > TW ? To : TW) + 1, j = 0;
        for (int it = 0; it < 60; it++) {
            const double m = 0.5 * (lo + hi), r = qin(m) - g0 * (m - T[0]) - LAT * face_water(m, s[0], 0.5 * h, &sf);
            if (r > 0) lo = m; else hi = m;
        }
        Tf = 0.5 * (lo + hi);
        j = face_water(Tf, s[0], 0.5 * h, &sf);
        qh[0] = g0 * (Tf - T[0]), qh[n] = 0; /* heat into cell i through its upper face (y down) */
        if (BETAP > 0) { /* the tray's contact, closed over the last half cell */
            const double gk = 2 * kof(s[n - 1] / S0) / h, Tbot = (BETAP * TP + gk * T[n - 1]) / (BETAP + gk);
            qh[n] = -BETAP * (TP - Tbot);
        }
        qw[0] = -j, qw[n] = 0;               /* water (kg/(m^2 s)) down through face i */
        for (int i = 1; i < n; i++) {
            const double ka = kof(s[i - 1] / S0), kb = kof(s[i] / S0);
            qh[i] = -2 * ka * kb / (ka + kb) * (T[i] - T[i - 1]) / h;
            const double th = 0.5 * (T[i] + T[i - 1]) + KELV;
            qw[i] = -RHO0 * KWAT * th * (s[i] * s[i] - s[i - 1] * s[i - 1]) / (2 * h);
        }
        bf = bf - (1 - bf) * expm1(-kbr(Tf) * bfac(sf) * dt); /* browning.c at the face's (T, s) */
        evap += j * dt;
        for (int i = 0; i < n; i++) {
            const double C = cof(s[i] / S0);
            T[i] += dt * (A[i] * qh[i] - A[i + 1] * qh[i + 1]) / (h * Vc[i] * C);
            s[i] += dt * (A[i] * qw[i] - A[i + 1] * qw[i + 1]) / (RHO0 * h * Vc[i]);
            if (s[i] < FLOOR) s[i] = FLOOR; /* the floor (never reached in practice: the flux vanishes with s) */
            if (NH && i == n - 1) T[i] = held_T((st + 1) * dt);
            if (T[i] > TB && s[i] > FLOOR) { /* water.c water_boil, per volume */
                double dm = C * (T[i] - TB) / LAT, spare = RHO0 * (s[i] - FLOOR);
                if (dm < spare) T[i] = TB;
                else dm = spare, T[i] -= dm * LAT / C;
                s[i] -= dm / RHO0, boiled += dm * h;
            }
        }
        const double t = (st + 1) * dt;
        if (t100 < 0 && Tf >= TB - 1e-9) t100 = t;
        if (tdry < 0 && sf < 0.01 * S0) tdry = t;
        if (!quiet && (st + 1) % per == 0) {
            printf("%6.2f %8.3f %.5f %.5f |", t / 60, Tf, sf, bf);
            for (int k = 0; k < 3; k++) {
                const double u = ys[k] / h - 0.5;
                double Ty, sy;
                if (u < 0) { /* between the face and the first centre */
                    const double f = ys[k] / (0.5 * h);
                    Ty = Tf + f * (T[0] - Tf), sy = sf + f * (s[0] - sf);
                } else {
                    const int i = (int)u;
                    const double f = u - i;
                    Ty = T[i] + f * (T[i + 1] - T[i]), sy = s[i] + f * (s[i + 1] - s[i]);
                }
                printf(" %7.3f %.5f", Ty, sy);
            }
            double dX = -1;
            for (int i = 0; i + 1 < n; i++)
                if (s[i] < 0.5 * S0 && s[i + 1] >= 0.5 * S0) {
                    dX = (i + 0.5 + (0.5 * S0 - s[i]) / (s[i + 1] - s[i])) * h;
                    break;
                }
            printf(" | %.4f %.4f | %.4f", boiled / (RHO0 * S0) * 1e3, evap / (RHO0 * S0) * 1e3, dX * 1e3);
            if (yc > 0) {
                const double u = yc / h - 0.5;
                const int i = (int)u;
                printf(" | T(%.1f mm) %.2f", yc * 1e3, T[i] + (u - i) * (T[i + 1] - T[i]));
            }
            printf("\n");
        }
    }
    printf("END h %g mm T0 %g evap %d diff %d vf %d: face %.3f degC s %.5f b %.5f; boiled %.4f evaporated %.4f mm; "
           "face at 100 degC at %.1f min, dry (s < 0.01 s0) at %.1f min\n",
           h * 1e3, T0, BW > 0, KWAT > 0, VF, Tf, sf, bf, boiled / (RHO0 * S0) * 1e3, evap / (RHO0 * S0) * 1e3, t100 / 60,
           tdry / 60);
    free(T), free(s), free(qh), free(qw), free(A), free(Vc);
    return 0;
}
