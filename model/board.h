/* board.h - strand board: a scene on a board over its serial link (rtl/boards/). */
#ifndef STRAND_BOARD_H
#define STRAND_BOARD_H

#include <stdbool.h>
#include <stdio.h>

#include "scene.h"

/* Run `frames` frames of the scene on the board at `port` (a serial device, or a
   pseudo-terminal); every frame's positions go to csv and hex (either may be NULL).
   False with a message in err. */
bool board_run(const scene *sc, const char *port, int frames, FILE *csv, FILE *hex, char *err, size_t len);

#endif
