/*
 * engine_body.h - the frame engine, written once for two number types.
 *
 * Included by engine_fixed.c and engine_double.c, which define:
 *   SIM, P(name)           the state type and the function prefix
 *   NUM                    the number type
 *   ADD SUB MUL AVG HALF   arithmetic (fixed: saturating, rounded ties-to-even)
 *   MAC2(a, b, c, d)       a b + c d (fixed: the exact products summed, rounded once)
 *   ABS                    magnitude
 *   LEN(d)                 length of a 3-vector (fixed: fx_sqrt of the exact sum of squares)
 *   DIV(a, b, dz)          a / b for a, b >= 0; *dz set when b == 0
 *   SDIV(a, b, dz)         a / b for a signed, b >= 0
 *   UNIT(a, b, dz)         a / b for |a| <= b, a unit-vector component (fixed: W-2 fraction bits)
 *   UMUL(a, u)             a times a unit-vector component
 *   LEG(h, d, miss)        sqrt(h^2 - |d|^2) (fixed: fx_sqrt of the exact difference); *miss if |d| > h
 *   ALONG(d, rest, t)      t = d rest / |d|, the vector of length rest along d; false when |d| = 0
 *                          (fixed: fx_mul(d, fx_div(rest, LEN(d))), or with a mantissa fx_along)
 *   UNITDIR(r, u)          u = r / |r| with W-2 fraction bits (fixed: UNIT of LEN(r), or with a mantissa
 *                          fx_along(r, 2^(W-2))); false when |r| = 0
 *   SPRING_DIR(d, len, u)  a spring's length |d| and unit vector u = d / |d|; false when |d| = 0
 *                          (fixed: LEN and SDIV, u in Q.F; with a mantissa fx_spring_dir, u in Q2.(W-2))
 *   DIRMUL(a, u)           a times a component of SPRING_DIR's u (MUL, or with a mantissa UMUL)
 *   FROM(x)                a scene constant in this number type
 *   LESS(a, b)             a < b
 *
 * Order of operations is part of the contract with the RTL: each line below that
 * combines two numbers is one saturating operation in hardware.
 *
 * A substep (Verlet): spring force pass, Verlet (+ mouse) pass over all nodes,
 * `iterations` constraint passes, ground pass. A frame samples the mouse first.
 * A constraint pass takes the nodes (centred rule) or edges (pairwise) in the scene's
 * order: serial, or redblack (colour by colour, scene.h).
 */

static bool P(node_pinned)(const SIM *s, int i) { return s->sc->pinned[i]; }

bool P(node_fixed)(const SIM *s, int i) { return s->sc->pinned[i] || s->grabbed == i; }

bool P(init)(SIM *s, const scene *sc, const fx_format *fmt)
{
    double h = scene_h(sc);
    scene_consts c;
    memset(s, 0, sizeof *s);
    s->sc = sc;
    if (fmt) s->fmt = *fmt;
    s->n = sc->n_nodes;
    s->dim = sc->dim;
    s->grabbed = -1;
    s->pos = calloc((size_t)s->n, sizeof *s->pos);
    s->prev = calloc((size_t)s->n, sizeof *s->prev);
    s->acc = calloc((size_t)s->n, sizeof *s->acc);
    s->vel = calloc((size_t)s->n, sizeof *s->vel);
    s->rest = calloc((size_t)(sc->n_edges ? sc->n_edges : 1), sizeof *s->rest);
    if (!s->pos || !s->prev || !s->acc || !s->vel || !s->rest) return false;

    /* Reset. A chain is laid out as the hardware does it, start + step, step, ...;
       the previous positions keep the scene's offsets from the positions. */
    for (int i = 0; i < s->n; i++)
        for (int k = 0; k < 3; k++) {
            if (sc->body == BODY_CHAIN)
                s->pos[i][k] = i == 0 ? FROM(sc->chain_start[k]) : ADD(s->pos[i - 1][k], FROM(sc->chain_step[k]));
            else
                s->pos[i][k] = FROM(sc->pos[i][k]);
            s->prev[i][k] = ADD(s->pos[i][k], FROM(sc->prev[i][k] - sc->pos[i][k]));
            /* Euler keeps velocity explicitly: the same initial motion */
            s->vel[i][k] = FROM((sc->pos[i][k] - sc->prev[i][k]) / h);
        }
    for (int e = 0; e < sc->n_edges; e++) s->rest[e] = FROM(sc->edges[e].rest);
    s->dist = FROM(sc->chain_rest);
    scene_constants(sc, &c);
    for (int k = 0; k < 3; k++) {
        s->box[k] = FROM(sc->mouse_box[k]);
    }
    s->impulse = FROM(c.impulse);
    s->ks = FROM(c.ks);
    s->kd = FROM(c.kd);
    s->friction = FROM(c.friction);
    s->ground = FROM(c.ground);
    s->h = FROM(c.h);
    STRAND_EFFECT_SIM_INIT /* the effects table's constants */
    return true;
}

void P(free)(SIM *s)
{
    free(s->pos);
    free(s->prev);
    free(s->acc);
    free(s->vel);
    free(s->rest);
    s->pos = s->prev = s->acc = s->vel = NULL;
    s->rest = NULL;
}

/* Is the pointer within the in-touch box of node i? (|mouse - node| < box on each axis) */
static bool P(in_touch)(const SIM *s, int i)
{
    for (int k = 0; k < s->dim; k++)
        if (!LESS(ABS(SUB(s->mouse[k], s->pos[i][k])), s->box[k])) return false;
    return true;
}

/*
 * The grab form of the mouse, with the pointer already sampled into s->mouse and
 * s->mouse_down: the button up releases the grabbed node; pressed with no node held,
 * the nearest free node inside the box (L1 distance, a saturating sum over the axes;
 * the lowest index on ties) is taken. The RTL's GRAB phase scans the nodes in this
 * order with these operations.
 */
void P(grab_update)(SIM *s)
{
    if (!s->mouse_down) {
        s->grabbed = -1;
        return;
    }
    if (s->grabbed >= 0) return;
    NUM best = FROM(0);
    for (int i = 0; i < s->n; i++) {
        if (P(node_pinned)(s, i) || !P(in_touch)(s, i)) continue;
        NUM d = ABS(SUB(s->mouse[0], s->pos[i][0]));
        for (int k = 1; k < s->dim; k++) d = ADD(d, ABS(SUB(s->mouse[k], s->pos[i][k])));
        if (s->grabbed < 0 || LESS(d, best)) {
            s->grabbed = i;
            best = d;
        }
    }
}

void P(begin_frame)(SIM *s)
{
    const scene *sc = s->sc;
    double m[3];
    bool down;
    if (!sc->en_mouse) return;
    scene_mouse_at(sc, s->frame, m, &down);
    for (int k = 0; k < 3; k++) s->mouse[k] = FROM(m[k]);
    s->mouse_down = down;
    if (sc->mouse == MOUSE_GRAB) P(grab_update)(s);
}

/*
 * Damped spring (references 001, 004): F = ks (l - l0) u + kd ((v_b - v_a) . u) u on a,
 * -F on b, u the unit vector from a to b. ks and kd are pre-scaled (init) so that F is
 * the position change per substep (Verlet) or the acceleration (Euler).
 */
void P(spring_edge)(SIM *s, int e)
{
    const scene_edge *ed = &s->sc->edges[e];
    NUM d[3] = {FROM(0), FROM(0), FROM(0)}, u[3] = {FROM(0), FROM(0), FROM(0)};
    NUM len, stretch, vn = FROM(0), f;
    int a = ed->a, b = ed->b;
    for (int k = 0; k < s->dim; k++) d[k] = SUB(s->pos[b][k], s->pos[a][k]);
    if (!SPRING_DIR(d, &len, u)) {
        s->skipped++; /* coincident ends: no direction, no force */
        return;
    }
    for (int k = 0; k < s->dim; k++) {
        NUM va, vb;
        if (s->sc->integrator == INTEGRATOR_VERLET) {
            va = SUB(s->pos[a][k], s->prev[a][k]);
            vb = SUB(s->pos[b][k], s->prev[b][k]);
        } else {
            va = s->vel[a][k];
            vb = s->vel[b][k];
        }
        vn = ADD(vn, DIRMUL(SUB(vb, va), u[k]));
    }
    stretch = SUB(len, s->rest[e]);
    f = MAC2(s->ks, stretch, s->kd, vn);
    for (int k = 0; k < s->dim; k++) {
        NUM fk = DIRMUL(f, u[k]);
        s->acc[a][k] = ADD(s->acc[a][k], fk);
        s->acc[b][k] = SUB(s->acc[b][k], fk);
    }
}

/* Verlet (reference 000, damping of reference 002): v = x - x-; v -= d v; v -= c h (v - w h) (wind);
   x- = x; x += v + g h^2 + F. */
bool P(verlet_node)(SIM *s, int i)
{
    const scene *sc = s->sc;
    if (P(node_pinned)(s, i)) return false;
    if (s->grabbed == i) { /* follows the pointer; releasing it keeps the pointer's last motion */
        for (int k = 0; k < s->dim; k++) {
            s->prev[i][k] = s->pos[i][k];
            s->pos[i][k] = s->mouse[k];
        }
        return true;
    }
    for (int k = 0; k < s->dim; k++) {
        NUM v = SUB(s->pos[i][k], s->prev[i][k]);
        NUM x;
        if (sc->en_damping) v = SUB(v, MUL(v, s->damping));
        if (sc->en_wind) v = SUB(v, MUL(SUB(v, s->wind[k]), s->drag)); /* air drag toward the wind */
        s->prev[i][k] = s->pos[i][k];
        x = ADD(s->pos[i][k], v);
        if (sc->en_gravity) x = ADD(x, s->gravity[k]);
        if (sc->en_springs) x = ADD(x, s->acc[i][k]);
        s->pos[i][k] = x;
    }
    return true;
}

/* Mouse impulse (reference 000): in touch, x- <- x + a if mouse.x < x- else x - a. */
void P(mouse_node)(SIM *s, int i)
{
    if (P(node_pinned)(s, i) || !s->mouse_down || !P(in_touch)(s, i)) return;
    s->prev[i][0] = LESS(s->mouse[0], s->prev[i][0]) ? ADD(s->pos[i][0], s->impulse) : SUB(s->pos[i][0], s->impulse);
}

/*
 * Projection along the previous direction (projection = previous; SHAKE). With q the
 * constraint's vector now (anchor to the moving end) and u the unit vector of the same
 * constraint at the start of the substep (the previous positions), the end moves along u
 * to where the length is `rest`: s = q.u, p = q - s u (q's part across u), and the new
 * vector is p + sgn(s) sqrt(rest^2 - |p|^2) u, the nearer of the two points where the
 * line along u meets the sphere of radius `rest`. The correction is along the start-of-
 * substep direction, as in a constraint force evaluated at the old positions, which keeps
 * energy bounded where the current direction loses it. False (the caller projects along
 * the current direction) when the start direction has no length or the line misses the
 * sphere (|p| > rest), counted in s->fallbacks.
 */
static bool P(along_previous)(SIM *s, const NUM q[3], int from, int to, NUM rest, NUM out[3])
{
    NUM r[3] = {FROM(0), FROM(0), FROM(0)}, u[3] = {FROM(0), FROM(0), FROM(0)}, p[3] = {FROM(0), FROM(0), FROM(0)};
    NUM dot = FROM(0), leg;
    bool miss;
    for (int k = 0; k < s->dim; k++) r[k] = SUB(s->prev[to][k], s->prev[from][k]);
    if (!UNITDIR(r, u)) {
        s->fallbacks++;
        return false;
    }
    for (int k = 0; k < s->dim; k++) dot = ADD(dot, UMUL(q[k], u[k]));
    for (int k = 0; k < s->dim; k++) p[k] = SUB(q[k], UMUL(dot, u[k]));
    leg = LEG(rest, p, &miss);
    if (miss) {
        s->fallbacks++;
        return false;
    }
    for (int k = 0; k < s->dim; k++) out[k] = LESS(dot, FROM(0)) ? SUB(p[k], UMUL(leg, u[k])) : ADD(p[k], UMUL(leg, u[k]));
    return true;
}

/* The point at distance `dist` from node `from`, toward node c. False for a zero length. */
static bool P(toward)(SIM *s, int from, int c, NUM out[3])
{
    NUM d[3] = {FROM(0), FROM(0), FROM(0)}, t[3];
    for (int k = 0; k < s->dim; k++) d[k] = SUB(s->pos[c][k], s->pos[from][k]);
    if (s->sc->projection == PROJECTION_PREVIOUS && P(along_previous)(s, d, from, c, s->dist, out)) {
        for (int k = 0; k < s->dim; k++) out[k] = ADD(s->pos[from][k], out[k]);
        return true;
    }
    if (!ALONG(d, s->dist, t)) {
        s->skipped++;
        return false;
    }
    for (int k = 0; k < s->dim; k++) out[k] = ADD(s->pos[from][k], t[k]);
    return true;
}

/*
 * Centred rule (reference 000): C moves to the mean of the point at `dist` from U and
 * the point at `dist` from D. At a rope end, or where one length is zero, the one
 * remaining point is used; with none, C stays.
 */
bool P(centred_node)(SIM *s, int i)
{
    NUM up[3], down[3];
    bool has_up, has_down;
    if (P(node_fixed)(s, i)) return false;
    has_up = i > 0 && P(toward)(s, i - 1, i, up);
    has_down = i + 1 < s->n && P(toward)(s, i + 1, i, down);
    for (int k = 0; k < s->dim; k++) {
        if (has_up && has_down)
            s->pos[i][k] = AVG(up[k], down[k]);
        else if (has_up)
            s->pos[i][k] = up[k];
        else if (has_down)
            s->pos[i][k] = down[k];
    }
    return has_up || has_down;
}

/*
 * Pairwise rule (references 001 struts, 002): the excess e = d - d * rest/|d| along
 * d = b - a is shared, a += e/2 and b -= e/2 (so the midpoint stays exactly), or taken
 * whole by the free end when the other is fixed.
 */
/* The excess of edge a-b on axis k shared: half each, or all of it on the free end. */
static void P(share)(SIM *s, int a, int b, bool fa, bool fb, int k, NUM excess)
{
    if (!fa && !fb) {
        NUM half = HALF(excess);
        s->pos[a][k] = ADD(s->pos[a][k], half);
        s->pos[b][k] = SUB(s->pos[b][k], half);
    } else if (fa) {
        s->pos[b][k] = SUB(s->pos[b][k], excess);
    } else {
        s->pos[a][k] = ADD(s->pos[a][k], excess);
    }
}

void P(pair_edge)(SIM *s, int e)
{
    const scene_edge *ed = &s->sc->edges[e];
    int a = ed->a, b = ed->b;
    bool fa = P(node_fixed)(s, a), fb = P(node_fixed)(s, b);
    NUM d[3] = {FROM(0), FROM(0), FROM(0)}, moved[3], t[3];
    if (fa && fb) return;
    for (int k = 0; k < s->dim; k++) d[k] = SUB(s->pos[b][k], s->pos[a][k]);
    if (s->sc->projection == PROJECTION_PREVIOUS && P(along_previous)(s, d, a, b, s->rest[e], moved)) {
        for (int k = 0; k < s->dim; k++) P(share)(s, a, b, fa, fb, k, SUB(d[k], moved[k]));
        return;
    }
    if (!ALONG(d, s->rest[e], t)) {
        s->skipped++;
        return;
    }
    for (int k = 0; k < s->dim; k++) P(share)(s, a, b, fa, fb, k, SUB(d[k], t[k]));
}

/*
 * Ground (reference 001): below the boundary, the node is put on it and its velocity
 * along the normal is reversed (x- = boundary + v); friction pulls the other axes'
 * previous positions toward the current ones by (1 - u).
 */
bool P(ground_node)(SIM *s, int i)
{
    const scene *sc = s->sc;
    int ax = sc->ground_axis;
    NUM z = s->pos[i][ax];
    bool below = sc->ground_sign > 0 ? LESS(z, s->ground) : LESS(s->ground, z);
    if (P(node_fixed)(s, i) || !below) return false;
    s->prev[i][ax] = ADD(s->ground, SUB(z, s->prev[i][ax]));
    s->pos[i][ax] = s->ground;
    for (int k = 0; k < s->dim; k++)
        if (k != ax) s->prev[i][k] = ADD(s->prev[i][k], MUL(SUB(s->pos[i][k], s->prev[i][k]), s->friction));
    return true;
}

static void P(force_pass)(SIM *s)
{
    for (int i = 0; i < s->n; i++)
        for (int k = 0; k < 3; k++) s->acc[i][k] = FROM(0);
    for (int e = 0; e < s->sc->n_edges; e++)
        if (s->sc->edges[e].kind == EDGE_SPRING) P(spring_edge)(s, e);
}

/* Explicit Euler (reference 002, C model only): x += v h; v += a h, with a from the old state. */
static void P(euler_substep)(SIM *s)
{
    const scene *sc = s->sc;
    if (sc->en_springs) P(force_pass)(s);
    for (int i = 0; i < s->n; i++) {
        if (P(node_pinned)(s, i)) continue;
        for (int k = 0; k < s->dim; k++) {
            NUM a = s->acc[i][k];
            if (sc->en_gravity) a = ADD(a, s->gravity[k]);
            s->prev[i][k] = s->pos[i][k];
            s->pos[i][k] = ADD(s->pos[i][k], MUL(s->vel[i][k], s->h));
            s->vel[i][k] = ADD(s->vel[i][k], MUL(a, s->h));
        }
    }
}

void P(substep)(SIM *s)
{
    const scene *sc = s->sc;
    if (sc->integrator == INTEGRATOR_EULER) {
        P(euler_substep)(s);
        return;
    }
    if (sc->en_springs) P(force_pass)(s);
    for (int i = 0; i < s->n; i++) {
        P(verlet_node)(s, i);
        if (sc->en_mouse && sc->mouse == MOUSE_IMPULSE) P(mouse_node)(s, i);
    }
    if (sc->en_constraints)
        for (int it = 0; it < sc->iterations; it++) {
            if (sc->rule == RULE_CENTRED && sc->order == ORDER_REDBLACK) /* even nodes, then odd */
                for (int colour = 0; colour < 2; colour++)
                    for (int i = colour; i < s->n; i += 2) P(centred_node)(s, i);
            else if (sc->rule == RULE_CENTRED)
                for (int i = 0; i < s->n; i++) P(centred_node)(s, i);
            else /* scene_set_order() put the edges in the pass's order */
                for (int e = 0; e < sc->n_edges; e++)
                    if (sc->edges[e].kind != EDGE_SPRING) P(pair_edge)(s, e);
        }
    if (sc->en_ground)
        for (int i = 0; i < s->n; i++) P(ground_node)(s, i);
}

void P(frame)(SIM *s)
{
    P(begin_frame)(s);
    for (int i = 0; i < s->sc->substeps; i++) P(substep)(s);
    s->frame++;
}
