/* render.c - draws edges, nodes, the ground and the pointer with cairo. */
#include "render.h"

#include <cairo.h>
#include <math.h>
#include <stdlib.h>

#include "engine.h"

/* 3D bodies are seen from an oblique camera, z up; 2D bodies as they are. */
static void project(const scene *sc, const double *p, double *u, double *w)
{
    if (sc->dim == 2) {
        *u = p[0];
        *w = sc->y_down ? -p[1] : p[1];
        return;
    }
    const double az = 0.6, el = 0.35;
    double x = p[0] * cos(az) - p[1] * sin(az);
    double depth = p[0] * sin(az) + p[1] * cos(az);
    *u = x;
    *w = p[2] * cos(el) + depth * sin(el);
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

static bool fit_hook(void *user, const runner *r, int frame, double (*pos)[3])
{
    fit_state *fs = user;
    (void)frame;
    for (int i = 0; i < r->sc->n_nodes; i++) {
        double u, w;
        project(r->sc, pos[i], &u, &w);
        if (isfinite(u) && isfinite(w)) grow_bounds(fs->v, u, w, &fs->any);
    }
    return true;
}

bool render_view_fit(render_view *v, const scene *sc, int frames)
{
    fit_state fs = {v, false};
    run_stats st;
    for (int i = 0; i < sc->n_nodes; i++) {
        double u, w;
        project(sc, sc->pos[i], &u, &w);
        grow_bounds(v, u, w, &fs.any);
    }
    if (!run_scene(sc, NUMBER_DOUBLE, NULL, frames, fit_hook, &fs, &st)) return false;
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
    project(sc, p, &u, &w);
    *px = (u - v->xmin) / (v->xmax - v->xmin) * v->width;
    *py = (v->ymax - w) / (v->ymax - v->ymin) * v->height;
}

bool render_png(const scene *sc, const render_view *v, double (*pos)[3], int frame, const char *path)
{
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, v->width, v->height);
    cairo_t *cr = cairo_create(surf);
    double scale = v->width / (v->xmax - v->xmin);
    double node_r = fmax(2.0, fmin(5.0, 0.25 * stats_length_scale(sc) * scale));
    cairo_status_t status;
    char label[96];

    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);

    if (sc->en_ground) { /* the plane, drawn as a line through its projected boundary */
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
    for (int i = 0; i < sc->n_nodes; i++) {
        double x, y;
        to_pixels(sc, v, pos[i], &x, &y);
        if (sc->pinned[i]) {
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_rectangle(cr, x - node_r, y - node_r, 2 * node_r, 2 * node_r);
        } else {
            cairo_set_source_rgb(cr, 0.2, 0.2, 0.25);
            cairo_arc(cr, x, y, node_r, 0, 6.283185307179586);
        }
        cairo_fill(cr);
    }
    if (sc->en_mouse) {
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

    status = cairo_surface_write_to_png(surf, path);
    cairo_destroy(cr);
    cairo_surface_destroy(surf);
    if (status != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "strand: cannot write %s: %s\n", path, cairo_status_to_string(status));
        return false;
    }
    return true;
}
