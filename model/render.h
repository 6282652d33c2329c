/* render.h - pictures of a body: one PNG per frame, drawn with cairo. */
#ifndef STRAND_RENDER_H
#define STRAND_RENDER_H

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double xmin, ymin, xmax, ymax; /* projected bounds */
    int width, height;             /* pixels */
    /* 3D: a perspective camera looking at `centre` from `distance` away (azimuth and
       elevation fixed), and the box the body stays in over the run (the floor's extent) */
    double centre[3], distance, lo[3], hi[3];
    bool live_pointer; /* the pointer is drawn by the caller (make demo), not from the scene's script */
} render_view;

/* Fit the view to the whole run (a double-precision pre-pass over `frames` frames). */
bool render_view_fit(render_view *v, const scene *sc, int frames);
/* Draw the body at one frame (with its label) on a cairo context (a cairo_t *, as void *
   so that this header needs no cairo), at the view's pixel size. False on failure. */
bool render_draw(void *cairo, const scene *sc, const render_view *v, double (*pos)[3], int frame);
/* The scene point under pixel (px, py) of a 2D view (z = 0); false for a 3D view. */
bool render_unproject(const scene *sc, const render_view *v, double px, double py, double *p);
/* Draw the body at one frame and write it as a PNG. False (with errno-style message on stderr) on failure. */
bool render_png(const scene *sc, const render_view *v, double (*pos)[3], int frame, const char *path);

#ifdef __cplusplus
}
#endif

#endif
