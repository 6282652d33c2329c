/*
 * fuzz_scene.c - libFuzzer target: arbitrary bytes as a scene file.
 *
 * Built with clang -fsanitize=fuzzer,address,undefined (scripts/stability.mk, make fuzz).
 * Each input is written to a file (scene_load takes a path) and loaded. It must:
 *  - never crash, hang, leak or hit undefined behaviour (the sanitizers and libFuzzer's
 *    -timeout and leak checks watch this);
 *  - load, or fail with exactly one "PATH:LINE: message" where LINE is 1..the file's line
 *    count (1 for an empty file) and the message is not empty.
 * A scene that loads and is small enough is then run for a few frames in both number
 * types, so the engine sees what the parser lets through.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine.h"
#include "scene.h"

static char path[64];

static void die(const char *what, const char *err)
{
    fprintf(stderr, "fuzz_scene: %s: '%s'\n", what, err);
    abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    scene sc;
    char err[SCENE_ERR_LEN];
    FILE *f;
    long lines = 0;
    if (!path[0]) snprintf(path, sizeof path, "/tmp/strand-fuzz-%d.scene", (int)getpid());
    f = fopen(path, "wb");
    if (!f) return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    for (size_t i = 0; i < size; i++) lines += data[i] == '\n';
    if (size && data[size - 1] != '\n') lines++;

    memset(err, 0, sizeof err);
    if (!scene_load(&sc, path, err)) {
        size_t n = strlen(path);
        char *end;
        long line;
        if (strncmp(err, path, n) != 0 || err[n] != ':') die("the message does not start with the path", err);
        line = strtol(err + n + 1, &end, 10);
        if (end == err + n + 1 || end[0] != ':' || end[1] != ' ' || !end[2]) die("the message is not 'path:line: message'", err);
        if (line < 1 || line > (lines > 0 ? lines : 1)) die("the line is outside the file", err);
        return 0;
    }
    /* Loaded: a few frames of it, if they are cheap (nodes x substeps x iterations bounded). */
    if ((long)sc.n_nodes * sc.substeps * sc.iterations + (long)sc.n_edges * sc.substeps <= 20000) {
        for (int kind = 0; kind < 2; kind++) {
            runner r;
            if (kind == NUMBER_FIXED && sc.number != NUMBER_FIXED) continue; /* values are only checked to fit a fixed scene */
            if (!runner_init(&r, &sc, (number_kind)kind, &sc.fmt)) continue;
            for (int fr = 0; fr < 3; fr++) runner_frame(&r);
            runner_free(&r);
        }
    }
    scene_free(&sc);
    return 0;
}
