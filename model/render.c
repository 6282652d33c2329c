/* render.c - draws edges, nodes, the ground and the pointer with cairo. */
#include "render.h"

#include <cairo.h>
#include <math.h>
#include <stdlib.h>

#include "engine.h"

/*
 * 2D bodies are drawn as they are. 3D bodies are seen in perspective by a camera at
 * azimuth AZ and elevation EL, `distance` from the centre of the box the body stays in,
 * with the up axis (z, or the ground's normal) up the picture. project() gives the
 * picture coordinates (u right, w up) and the depth factor (> 1 nearer, < 1 farther),
 * which sets the size and shade of a node.
 */
#define CAM_AZ 0.6
#define CAM_EL 0.45

static int up_axis(const scene *sc) { return sc->en_ground ? sc->ground_axis : 2; }

static void project(const scene *sc, const render_view *v, const double *p, double *u, double *w, double *near)
{
    if (sc->dim == 2) {
        *u = p[0];
        *w = sc->y_down ? -p[1] : p[1];
        if (near) *near = 1;
        return;
    }
    /* the up axis and the two others, in a right-handed order */
    int up = up_axis(sc), a1 = (up + 1) % 3, a2 = (up + 2) % 3;
    double x = p[a1] - v->centre[a1], y = p[a2] - v->centre[a2], z = p[up] - v->centre[up];
    double side = x * cos(CAM_AZ) - y * sin(CAM_AZ);
    double ahead = x * sin(CAM_AZ) + y * cos(CAM_AZ);            /* away from the camera, level */
    double height = z * cos(CAM_EL) - ahead * sin(CAM_EL);
    double depth = ahead * cos(CAM_EL) + z * sin(CAM_EL);         /* along the line of sight */
    double f = v->distance / fmax(v->distance + depth, 1e-6 * v->distance);
    *u = side * f;
    *w = height * f;
    if (near) *near = f;
}

static void grow_bounds(render_view *v, double u, double w, bool *any)
{
    if (!*any || u < v->xmin) v->xmin = u;
    if (!*any || u > v->xmax) v->xmax = u;
    if (!*any || w < v->ymin) v->ymin = w;
    if (!*any || w > v->ymax) v->ymax = w;
    *any = true;
}

typedef struct {
    render_view *v;
    bool any;
} fit_state;

static void grow_box(render_view *v, const double *p, bool *any)
{
    for (int a = 0; a < 3; a++) {
        if (!isfinite(p[a])) return;
    }
    for (int a = 0; a < 3; a++) {
        if (!*any || p[a] < v->lo[a]) v->lo[a] = p[a];
        if (!*any || p[a] > v->hi[a]) v->hi[a] = p[a];
    }
    *any = true;
}

static bool fit_hook(void *user, const runner *r, int frame, double (*pos)[3])
{
    fit_state *fs = user;
    (void)frame;
    for (int i = 0; i < r->sc->n_nodes; i++) grow_box(fs->v, pos[i], &fs->any);
    return true;
}

/* The floor: the ground plane, or (3D without a ground) the plane just below the body. */
static double floor_level(const scene *sc, const render_view *v)
{
    return sc->en_ground ? sc->ground_level : v->lo[up_axis(sc)];
}

bool render_view_fit(render_view *v, const scene *sc, int frames)
{
    fit_state fs = {v, false};
    run_stats st;
    for (int i = 0; i < sc->n_nodes; i++) grow_box(v, sc->pos[i], &fs.any);
    if (!run_scene(sc, NUMBER_DOUBLE, NULL, frames, fit_hook, &fs, &st)) return false;
    if (!fs.any)
        for (int a = 0; a < 3; a++) v->lo[a] = -1, v->hi[a] = 1;
    if (sc->dim == 3) { /* the camera, then the picture bounds of the box and its floor */
        double size = 0;
        int up = up_axis(sc);
        double fl = floor_level(sc, v);
        if (fl < v->lo[up]) v->lo[up] = fl;
        if (fl > v->hi[up]) v->hi[up] = fl;
        for (int a = 0; a < 3; a++) {
            v->centre[a] = (v->lo[a] + v->hi[a]) / 2;
            size = fmax(size, v->hi[a] - v->lo[a]);
        }
        if (size <= 0) size = 1;
        /* the floor reaches a quarter of the body's size beyond it on each side */
        for (int a = 0; a < 3; a++)
            if (a != up) v->lo[a] -= size / 4, v->hi[a] += size / 4;
        v->distance = 2.5 * size;
    }
    fs.any = false;
    for (int c = 0; c < 8; c++) {
        double p[3], u, w;
        for (int a = 0; a < 3; a++) p[a] = (c >> a) & 1 ? v->hi[a] : v->lo[a];
        if (sc->dim == 2) p[2] = 0;
        project(sc, v, p, &u, &w, NULL);
        grow_bounds(v, u, w, &fs.any);
    }
    double span = fmax(v->xmax - v->xmin, v->ymax - v->ymin);
    if (span <= 0) span = 1;
    double margin = 0.08 * span;
    v->xmin -= margin, v->xmax += margin, v->ymin -= margin, v->ymax += margin;
    if (sc->en_ground && sc->dim == 2 && sc->ground_axis == 1) {
        double gw = sc->y_down ? -sc->ground_level : sc->ground_level;
        if (gw - margin < v->ymin) v->ymin = gw - margin;
        if (gw + margin > v->ymax) v->ymax = gw + margin;
    }
    double aspect = (v->xmax - v->xmin) / (v->ymax - v->ymin);
    v->width = 640;
    /* an even height: H.264 in yuv420p wants even sizes, and padding drew a black bar */
    v->height = 2 * (int)(fmin(960, fmax(160, 640 / aspect)) / 2);
    /* keep the scale equal on both axes: widen the short side */
    double sx = (v->xmax - v->xmin) / v->width, sy = (v->ymax - v->ymin) / v->height;
    if (sx > sy) {
        double c = (v->ymin + v->ymax) / 2, half = sx * v->height / 2;
        v->ymin = c - half, v->ymax = c + half;
    } else {
        double c = (v->xmin + v->xmax) / 2, half = sy * v->width / 2;
        v->xmin = c - half, v->xmax = c + half;
    }
    return true;
}

static void to_pixels(const scene *sc, const render_view *v, const double *p, double *px, double *py)
{
    double u, w;
    project(sc, v, p, &u, &w, NULL);
    *px = (u - v->xmin) / (v->xmax - v->xmin) * v->width;
    *py = (v->ymax - w) / (v->ymax - v->ymin) * v->height;
}

/* 3D: the floor (the ground plane, or the plane under the body) as a shaded grid over the
   box the body stays in, and the body's shadow on it (straight down the up axis). */
static void draw_floor(cairo_t *cr, const scene *sc, const render_view *v, double (*pos)[3])
{
    int up = up_axis(sc), a1 = (up + 1) % 3, a2 = (up + 2) % 3;
    double fl = floor_level(sc, v), p[3], x, y;
    double span = fmax(v->hi[a1] - v->lo[a1], v->hi[a2] - v->lo[a2]);
    double step = pow(10, floor(log10(span / 4)));               /* a round spacing, 4 to 40 lines */
    if (span / step > 20) step *= 5;
    else if (span / step > 10) step *= 2;
    p[up] = fl;
    /* the plane */
    cairo_set_source_rgb(cr, sc->en_ground ? 0.90 : 0.95, sc->en_ground ? 0.87 : 0.95, sc->en_ground ? 0.80 : 0.95);
    for (int c = 0; c < 4; c++) {
        p[a1] = (c == 1 || c == 2) ? v->hi[a1] : v->lo[a1];
        p[a2] = c >= 2 ? v->hi[a2] : v->lo[a2];
        to_pixels(sc, v, p, &x, &y);
        if (c == 0) cairo_move_to(cr, x, y);
        else cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
    cairo_fill(cr);
    /* the grid */
    cairo_set_source_rgb(cr, 0.72, 0.68, 0.60);
    cairo_set_line_width(cr, 0.8);
    for (int dir = 0; dir < 2; dir++) {
        int along = dir ? a1 : a2, across = dir ? a2 : a1;
        for (double g = ceil(v->lo[across] / step) * step; g <= v->hi[across]; g += step) {
            p[across] = g;
            p[along] = v->lo[along];
            to_pixels(sc, v, p, &x, &y);
            cairo_move_to(cr, x, y);
            p[along] = v->hi[along];
            to_pixels(sc, v, p, &x, &y);
            cairo_line_to(cr, x, y);
        }
    }
    cairo_stroke(cr);
    /* the shadow: every edge and node dropped onto the floor */
    cairo_set_source_rgb(cr, 0.62, 0.60, 0.56);
    cairo_set_line_width(cr, 2);
    for (int e = 0; e < sc->n_edges; e++) {
        double q[3], bx, by;
        for (int a = 0; a < 3; a++) q[a] = pos[sc->edges[e].a][a];
        q[up] = fl;
        to_pixels(sc, v, q, &x, &y);
        for (int a = 0; a < 3; a++) q[a] = pos[sc->edges[e].b][a];
        q[up] = fl;
        to_pixels(sc, v, q, &bx, &by);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, bx, by);
    }
    cairo_stroke(cr);
    for (int i = 0; i < sc->n_nodes; i++) {
        double q[3];
        for (int a = 0; a < 3; a++) q[a] = pos[i][a];
        q[up] = fl;
        to_pixels(sc, v, q, &x, &y);
        cairo_arc(cr, x, y, 2.5, 0, 6.283185307179586);
        cairo_fill(cr);
    }
}

bool render_unproject(const scene *sc, const render_view *v, double px, double py, double *p)
{
    if (sc->dim != 2) return false;
    double u = v->xmin + px / v->width * (v->xmax - v->xmin);
    double w = v->ymax - py / v->height * (v->ymax - v->ymin);
    p[0] = u, p[1] = sc->y_down ? -w : w, p[2] = 0;
    return true;
}

bool render_draw(void *cairo, const scene *sc, const render_view *v, double (*pos)[3], int frame)
{
    cairo_t *cr = cairo;
    double scale = v->width / (v->xmax - v->xmin);
    double node_r = fmax(2.0, fmin(5.0, 0.25 * stats_length_scale(sc) * scale));
    char label[96];

    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);

    if (sc->dim == 3) draw_floor(cr, sc, v, pos);
    else if (sc->en_ground) { /* the boundary, a line */
        double a[3] = {0, 0, 0}, b[3] = {0, 0, 0}, ax, ay, bx, by;
        int other = sc->ground_axis == 0 ? 1 : 0;
        a[sc->ground_axis] = b[sc->ground_axis] = sc->ground_level;
        a[other] = -1e6, b[other] = 1e6;
        to_pixels(sc, v, a, &ax, &ay);
        to_pixels(sc, v, b, &bx, &by);
        cairo_set_source_rgb(cr, 0.55, 0.45, 0.35);
        cairo_set_line_width(cr, 2);
        cairo_move_to(cr, ax, ay);
        cairo_line_to(cr, bx, by);
        cairo_stroke(cr);
    }
    for (int e = 0; e < sc->n_edges; e++) {
        const scene_edge *ed = &sc->edges[e];
        double ax, ay, bx, by;
        to_pixels(sc, v, pos[ed->a], &ax, &ay);
        to_pixels(sc, v, pos[ed->b], &bx, &by);
        if (ed->kind == EDGE_STRUT) cairo_set_source_rgb(cr, 0.70, 0.15, 0.10), cairo_set_line_width(cr, 3.5);
        else if (ed->kind == EDGE_SPRING) cairo_set_source_rgb(cr, 0.10, 0.55, 0.25), cairo_set_line_width(cr, 1.2);
        else cairo_set_source_rgb(cr, 0.15, 0.25, 0.60), cairo_set_line_width(cr, 2);
        cairo_move_to(cr, ax, ay);
        cairo_line_to(cr, bx, by);
        cairo_stroke(cr);
    }
    /* nodes far to near, so that a nearer one covers a farther one; in 3D a nearer node
       is drawn larger and darker (the depth cue beside the perspective and the shadows) */
    int *order = malloc((size_t)sc->n_nodes * sizeof *order);
    double *near = malloc((size_t)sc->n_nodes * sizeof *near);
    if (!order || !near) {
        free(order);
        free(near);
        fprintf(stderr, "strand: out of memory drawing frame %d\n", frame);
        return false;
    }
    for (int i = 0; i < sc->n_nodes; i++) {
        double u, w;
        project(sc, v, pos[i], &u, &w, &near[i]);
        order[i] = i;
    }
    for (int i = 1; i < sc->n_nodes; i++) /* insertion sort: bodies are small */
        for (int j = i; j > 0 && near[order[j - 1]] > near[order[j]]; j--) {
            int t = order[j];
            order[j] = order[j - 1], order[j - 1] = t;
        }
    for (int k = 0; k < sc->n_nodes; k++) {
        int i = order[k];
        double x, y, r = node_r * (sc->dim == 3 ? near[i] : 1);
        double shade = sc->dim == 3 ? fmin(0.45, fmax(0.05, 0.25 - 0.8 * (near[i] - 1))) : 0.2;
        to_pixels(sc, v, pos[i], &x, &y);
        if (sc->pinned[i]) {
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_rectangle(cr, x - r, y - r, 2 * r, 2 * r);
        } else {
            cairo_set_source_rgb(cr, shade, shade, shade + 0.05);
            cairo_arc(cr, x, y, r, 0, 6.283185307179586);
        }
        cairo_fill(cr);
    }
    free(order);
    free(near);
    if (sc->en_mouse && !v->live_pointer) {
        double m[3], x, y;
        bool down;
        scene_mouse_at(sc, frame > 0 ? frame - 1 : 0, m, &down);
        if (down) {
            to_pixels(sc, v, m, &x, &y);
            cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
            cairo_set_line_width(cr, 1.5);
            cairo_move_to(cr, x - 8, y), cairo_line_to(cr, x + 8, y);
            cairo_move_to(cr, x, y - 8), cairo_line_to(cr, x, y + 8);
            cairo_stroke(cr);
        }
    }
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_select_font_face(cr, "monospace", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 12);
    snprintf(label, sizeof label, "%s  frame %d", sc->name, frame);
    cairo_move_to(cr, 8, 16);
    cairo_show_text(cr, label);
    return true;
}

bool render_png(const scene *sc, const render_view *v, double (*pos)[3], int frame, const char *path)
{
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, v->width, v->height);
    cairo_t *cr = cairo_create(surf);
    bool drawn = render_draw(cr, sc, v, pos, frame);
    cairo_status_t status = drawn ? cairo_surface_write_to_png(surf, path) : CAIRO_STATUS_NO_MEMORY;
    cairo_destroy(cr);
    cairo_surface_destroy(surf);
    if (status != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "strand: cannot write %s: %s\n", path, cairo_status_to_string(status));
        return false;
    }
    return true;
}
