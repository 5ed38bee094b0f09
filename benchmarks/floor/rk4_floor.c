/*
 * The floor of the speed benchmark: a plain fixed-step RK4 of the rocking wall, in C.
 *
 * Written from the equations of docs/model.md (Eq. 10 of the paper with the base reaction of
 * the compressed zone, the impacts, Eq. 12 at rupture, toe crushing, and the `overturning`
 * collapse rule decided on the mechanical energy), not from the numba kernel, so that
 * benchmarks/bench_floor.py can compare the two side by side: same walls, same records, same
 * IDA rule, and the collapse multipliers must agree within the accuracy bar.
 *
 * Fixed step h (the largest step; a sample interval is divided into equal steps).  An event
 * (impact, rupture, crushing, fall) is detected by the sign of the level function at the end of
 * a step and located by bisection of the step length, re-integrating from the step's start;
 * the jump is applied there and the integration restarts from it.  Uplift from rest is solved
 * exactly on the linear ground acceleration.  Everything is SI, per metre of wall.
 */
#include <math.h>

typedef struct {
    double g;                /* gravity [m/s2] */
    double p2;               /* p^2 [1/s2] */
    double sin_a, cos_a;     /* slenderness alpha about the base corner */
    double tan_uplift;       /* (B - x_W)/H: uplift threshold in g */
    double xi;               /* x_W/(2R): the base reaction term (0: edge pivot) */
    double k_bar;            /* K of Eq. 10 while the acting bar is intact */
    double kappa;            /* 2 b_r E A/(H W): bar force over the weight per sin(|theta|/2) */
    double theta_max;        /* rupture rotation of an intact bar (INFINITY: never) */
    double theta_cr;         /* toe-crushing rotation of an intact bar (INFINITY: never) */
    double rupture_energy;   /* U_r(theta_max)/I0 [1/s2], Eq. 12 */
    double e_impact;         /* velocity ratio at an impact */
    double barrier_intact;   /* V at the barrier angle of a side with an intact bar [1/s2] */
    double angle_intact;     /* that barrier angle [rad] */
    double barrier_broken;   /* the same for a side without a bar */
    double angle_broken;
    double h;                /* fixed step [s] */
    double max_free;         /* longest free vibration after the input [s] */
    int one_sided;
    int bar_mode;            /* 0 none, 1 one centred bar for both sides, 2 one bar per face */
} Params;

/* theta'' [rad/s2] in the regime s, ground acceleration u [g] */
static double accel(double th, double s, double u, double k, double kap, const Params *P)
{
    double st = sin(th), ct = cos(th);
    double f = s * P->sin_a * ct - P->cos_a * st + u * (P->cos_a * ct + s * P->sin_a * st) + k * st;
    if (P->xi != 0.0) {
        double half = 0.5 * (1.0 - ct);
        double n = 1.0 + kap * sqrt(half > 0.0 ? half : 0.0);
        f -= s * P->xi * n * n * ct;
    }
    return -P->p2 * f;
}

/* V(theta) per unit I0: gravity, the bar, and the base reaction (closed-form integral) */
static double potential(double th, double k, double kap, const Params *P)
{
    double a = fabs(th);
    double alpha = atan2(P->sin_a, P->cos_a);
    double v = cos(alpha - a) + k * (1.0 - cos(a));
    if (P->xi != 0.0) {
        double c = cos(0.5 * a);
        double integral = sin(a) + 2.0 * kap * (2.0 * c - 4.0 / 3.0 * c * c * c - 2.0 / 3.0)
                          + 0.5 * kap * kap * (sin(a) - 0.5 * a - 0.25 * sin(2.0 * a));
        v -= P->xi * integral;
    }
    return P->p2 * v;
}

static void rk4(double th, double om, double h, double u0, double slope, double s, double k,
                double kap, const Params *P, double *th1, double *om1)
{
    double um = u0 + 0.5 * h * slope, ue = u0 + h * slope;
    double a1 = accel(th, s, u0, k, kap, P);
    double t2 = th + 0.5 * h * om, w2 = om + 0.5 * h * a1;
    double a2 = accel(t2, s, um, k, kap, P);
    double t3 = th + 0.5 * h * w2, w3 = om + 0.5 * h * a2;
    double a3 = accel(t3, s, um, k, kap, P);
    double t4 = th + h * w3, w4 = om + h * a3;
    double a4 = accel(t4, s, ue, k, kap, P);
    *th1 = th + h / 6.0 * (om + 2.0 * w2 + 2.0 * w3 + w4);
    *om1 = om + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

enum { EV_NONE, EV_IMPACT, EV_RUPTURE, EV_CRUSH, EV_FALL };

/* the first level that y = s*theta has crossed (in the order a wall meets them) */
static int crossed(double y, int bar_on, const Params *P)
{
    if (y <= 0.0) return EV_IMPACT;
    if (bar_on && y >= P->theta_cr && P->theta_cr <= P->theta_max) return EV_CRUSH;
    if (bar_on && y >= P->theta_max) return EV_RUPTURE;
    if (bar_on && y >= P->theta_cr) return EV_CRUSH;
    if (y >= 0.5 * M_PI) return EV_FALL;
    return EV_NONE;
}

static int cannot_fall(double th, double om, double s, int ip, int in, const Params *P)
{
    int on = s > 0.0 ? ip : in;
    if (fabs(th) >= (on ? P->angle_intact : P->angle_broken)) return 0;
    double e = 0.5 * om * om + potential(th, on ? P->k_bar : 0.0, on ? P->kappa : 0.0, P);
    if (e >= (ip ? P->barrier_intact : P->barrier_broken)) return 0;
    if (!P->one_sided && e >= (in ? P->barrier_intact : P->barrier_broken)) return 0;
    return 1;
}

/*
 * One time history under scale*acc (acc [m/s2] every dt [s]).  Returns 1 when the wall
 * collapses (falls or crushes its toe), 0 when it can no longer fall, -1 when the fate is not
 * certain after max_free seconds of free vibration.  *steps receives the RK4 steps taken and
 * *peak the largest |theta| at the ends of the steps and at the events [rad].
 */
int floor_simulate(const double *acc, long n, double dt, double scale, const Params *P,
                   long *steps, double *peak)
{
    double inv_g = scale / P->g;
    double p = sqrt(P->p2);
    double th = 0.0, om = 0.0, s = 1.0;
    int resting = 1;
    int ip = P->bar_mode != 0, in = P->bar_mode != 0;
    long nsteps = 0;
    double pk = 0.0;
    long n_free_max = (long)ceil(P->max_free / dt);
    int per = (int)ceil(dt / P->h - 1e-9);
    double hstep = dt / (per > 0 ? per : 1);

    for (long i = 0;; i++) {
        int free_motion = i >= n - 1;
        if (free_motion) {
            if (resting || cannot_fall(th, om, s, ip, in, P)) { *peak = pk; *steps = nsteps; return 0; }
            if (i - (n - 1) >= n_free_max) { *peak = pk; *steps = nsteps; return -1; }
        }
        double ua = i < n ? acc[i] * inv_g : 0.0;
        double ub = i + 1 < n ? acc[i + 1] * inv_g : 0.0;
        double slope = (ub - ua) / dt;
        double x = 0.0;
        while (x < dt) {
            if (resting) {
                double tu = P->tan_uplift;
                double ux = ua + slope * x, ue = ua + slope * dt;
                double side = 0.0, at = dt;
                if (ux < -tu) { side = 1.0; at = x; }
                else if (!P->one_sided && ux > tu) { side = -1.0; at = x; }
                else if (ue < -tu) { side = 1.0; at = x + (-tu - ux) / slope; }
                else if (!P->one_sided && ue > tu) { side = -1.0; at = x + (tu - ux) / slope; }
                x = at;
                if (side != 0.0) { resting = 0; s = side; th = 0.0; om = 0.0; }
                continue;
            }
            int on = s > 0.0 ? ip : in;
            double k = on ? P->k_bar : 0.0, kap = on ? P->kappa : 0.0;
            double rest = dt - x;
            double hh = rest < hstep * 1.000001 ? rest : hstep;
            double u0 = ua + slope * x;
            double th1, om1;
            rk4(th, om, hh, u0, slope, s, k, kap, P, &th1, &om1);
            nsteps++;
            int ev = crossed(s * th1, on, P);
            if (ev == EV_NONE) {
                th = th1; om = om1; x += hh;
                if (fabs(th) > pk) pk = fabs(th);
                if (free_motion && cannot_fall(th, om, s, ip, in, P)) { *peak = pk; *steps = nsteps; return 0; }
                continue;
            }
            /* locate the event: the shortest sub-step that has crossed a level */
            double lo = 0.0, hi = hh;
            for (int it = 0; it < 60 && hi - lo > 1e-13 * dt; it++) {
                double mid = 0.5 * (lo + hi), tm, wm;
                rk4(th, om, mid, u0, slope, s, k, kap, P, &tm, &wm);
                if (crossed(s * tm, on, P) != EV_NONE) hi = mid; else lo = mid;
            }
            rk4(th, om, hi, u0, slope, s, k, kap, P, &th1, &om1);
            ev = crossed(s * th1, on, P);
            x += hi;
            if (fabs(th1) > pk) pk = fabs(th1);
            if (ev == EV_FALL || ev == EV_CRUSH) { *peak = pk; *steps = nsteps; return 1; }
            if (ev == EV_IMPACT) {
                th = 0.0;
                if (P->one_sided) om = -P->e_impact * om1;
                else { om = P->e_impact * om1; s = -s; }
                if (fabs(om) < 1e-7 * p) { om = 0.0; resting = 1; }
            } else { /* rupture, Eq. 12 */
                th = s * P->theta_max;
                if (P->bar_mode == 1) { ip = 0; in = 0; }
                else if (s > 0.0) ip = 0; else in = 0;
                om = copysign(sqrt(om1 * om1 + 2.0 * P->rupture_energy), om1);
            }
            if (free_motion && (resting || cannot_fall(th, om, s, ip, in, P))) {
                *peak = pk; *steps = nsteps; return 0;
            }
        }
    }
}
