/*
 * board.c - strand board: a scene on a board over its serial link.
 *
 * The board runs strand_axil behind rtl/boards/uart_axil_bridge.v. Its protocol (bytes,
 * big-endian fields): 'W' A1 A0 D3 D2 D1 D0 -> one byte, the write's BRESP (0 OKAY, 2
 * SLVERR); 'R' A1 A0 -> RRESP and D3 D2 D1 D0. The registers are strand_axil's
 * (rtl/strand_axil.v: the core's registers at 4 a, CTRL, STATUS, FRAMES, INFO, NODES, the
 * mouse, the node window).
 *
 * The run: INFO and NODES must match the build the scene needs (W, F, DIM, M, K); the
 * setup writes (hw_setup_writes: the same words the lockstep harness writes) go out one
 * by one, then STATUS is polled until the init walk is done; each frame writes the
 * scene's mouse, starts the frame (CTRL), polls STATUS until it is finished, clears the
 * flag and reads every node back. Positions go to --csv (as `strand run --csv` writes
 * them) and --hex (as `strand run --hex`: the raw words, so that the two compare byte for
 * byte).
 */
#define _DEFAULT_SOURCE
#include "board.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include "hwgen.h"
#include "sim.h"

enum {
    A_CTRL = 0x100, A_STATUS = 0x104, A_FRAMES = 0x108, A_INFO = 0x10C, A_NODES = 0x110,
    A_MOUSE_X = 0x114, A_MOUSE_DOWN = 0x120,
};
#define REPLY_TIMEOUT_MS 5000
#define POLL_LIMIT 1000000L   /* STATUS reads before a frame counts as hung */

typedef struct {
    int fd;
    char *err;
    size_t len;
} link_t;

static bool fail(link_t *l, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(l->err, l->len, fmt, ap);
    va_end(ap);
    return false;
}

static bool send_all(link_t *l, const uint8_t *b, size_t n)
{
    while (n) {
        ssize_t w = write(l->fd, b, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return fail(l, "writing to the board: %s", strerror(errno));
        b += w, n -= (size_t)w;
    }
    return true;
}

static bool recv_all(link_t *l, uint8_t *b, size_t n)
{
    while (n) {
        struct pollfd p = {l->fd, POLLIN, 0};
        int r = poll(&p, 1, REPLY_TIMEOUT_MS);
        if (r < 0 && errno == EINTR) continue;
        if (r == 0) return fail(l, "the board did not answer within %d ms", REPLY_TIMEOUT_MS);
        ssize_t got = read(l->fd, b, n);
        if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (got <= 0) return fail(l, "reading from the board: %s", got ? strerror(errno) : "the link closed");
        b += got, n -= (size_t)got;
    }
    return true;
}

static bool reg_write(link_t *l, unsigned addr, uint32_t data)
{
    uint8_t cmd[7] = {'W', (uint8_t)(addr >> 8), (uint8_t)addr, (uint8_t)(data >> 24), (uint8_t)(data >> 16),
                      (uint8_t)(data >> 8), (uint8_t)data};
    uint8_t resp;
    if (!send_all(l, cmd, sizeof cmd) || !recv_all(l, &resp, 1)) return false;
    if (resp != 0) return fail(l, "write of 0x%x at 0x%03x answered 0x%02x (not OKAY)", data, addr, resp);
    return true;
}

static bool reg_read(link_t *l, unsigned addr, uint32_t *data)
{
    uint8_t cmd[3] = {'R', (uint8_t)(addr >> 8), (uint8_t)addr}, ans[5];
    if (!send_all(l, cmd, sizeof cmd) || !recv_all(l, ans, sizeof ans)) return false;
    if (ans[0] != 0) return fail(l, "read of 0x%03x answered 0x%02x (not OKAY)", addr, ans[0]);
    *data = (uint32_t)ans[1] << 24 | (uint32_t)ans[2] << 16 | (uint32_t)ans[3] << 8 | ans[4];
    return true;
}

/* A W-bit word sign-extended to 32 bits (what the shell's registers hold). */
static uint32_t sext(uint32_t v, int w)
{
    return w == 32 ? v : (uint32_t)(((int32_t)(v << (32 - w))) >> (32 - w));
}

static bool wait_status(link_t *l, uint32_t mask, uint32_t want, const char *what)
{
    uint32_t st = 0;
    for (long i = 0; i < POLL_LIMIT; i++) {
        if (!reg_read(l, A_STATUS, &st)) return false;
        if ((st & mask) == want) return true;
    }
    return fail(l, "%s: STATUS stayed 0x%x", what, st);
}

static bool open_port(link_t *l, const char *port)
{
    l->fd = open(port, O_RDWR | O_NOCTTY);
    if (l->fd < 0) return fail(l, "%s: %s", port, strerror(errno));
    struct termios t;
    if (tcgetattr(l->fd, &t) == 0) { /* raw bytes at 115200 baud, 8N1 (a pseudo-terminal ignores the rate) */
        cfmakeraw(&t);
        cfsetispeed(&t, B115200);
        cfsetospeed(&t, B115200);
        t.c_cflag |= CLOCAL | CREAD;
        t.c_cflag &= ~(tcflag_t)(CSTOPB | PARENB);
        tcsetattr(l->fd, TCSANOW, &t);
    }
    return true;
}

bool board_run(const scene *sc, const char *port, int frames, FILE *csv, FILE *hex, char *err, size_t len)
{
    link_t l = {-1, err, len};
    hw_params hp;
    uint32_t info, nodes, v;
    bool ok = false;
    hw_params_of(sc, &hp);
    hw_write *writes = malloc(65536 * sizeof *writes);
    if (!writes) return fail(&l, "out of memory");
    if (!open_port(&l, port)) goto done;
    if (!reg_read(&l, A_INFO, &info) || !reg_read(&l, A_NODES, &nodes)) goto done;
    if ((int)(info >> 24) != hp.dim || (int)(info >> 16 & 0xff) != hp.f || (int)(info >> 8 & 0xff) != hp.w ||
        (int)(nodes >> 16) != hp.m || (int)(nodes & 0xffff) != hp.k) {
        fail(&l, "the board holds another build (DIM %u, Q%u.%u, %u x %u nodes) than %s needs (DIM %d, Q%d.%d, %d x %d): "
                 "make bitstream SCENE=%s", info >> 24, (info >> 8 & 0xff) - (info >> 16 & 0xff), info >> 16 & 0xff,
             nodes >> 16, nodes & 0xffff, sc->path, hp.dim, hp.w - hp.f, hp.f, hp.m, hp.k, sc->path);
        goto done;
    }
    sim_fx init;
    sim_fx_init(&init, sc, &sc->fmt);
    int n = hw_setup_writes(sc, &init, writes, 65536);
    sim_fx_free(&init);
    if (!wait_status(&l, 1, 0, "before the setup")) goto done;
    for (int i = 0; i < n; i++)
        if (!reg_write(&l, 4u * (unsigned)writes[i].addr, writes[i].data)) goto done;
    if (!wait_status(&l, 1, 0, "the init walk")) goto done;
    int digits = (hp.w + 3) / 4;
    uint32_t mask = hp.w == 32 ? 0xffffffffu : (1u << hp.w) - 1;
    unsigned node_base = 1u << hp.axil_nb;
    for (int f = 0; f < frames; f++) {
        double m[3];
        bool down;
        scene_mouse_at(sc, f, m, &down);
        for (int k = 0; k < hp.dim; k++)
            if (!reg_write(&l, A_MOUSE_X + 4u * (unsigned)k, sext(hw_word(&sc->fmt, fx_from_double(&sc->fmt, m[k])), hp.w)))
                goto done;
        if (!reg_write(&l, A_MOUSE_DOWN, sc->en_mouse && down) || !reg_write(&l, A_CTRL, 1) ||
            !wait_status(&l, 3, 2, "the frame") || !reg_write(&l, A_STATUS, 2))
            goto done;
        for (int i = 0; i < sc->n_nodes; i++) {
            uint32_t addr = hw_node_addr(&hp, i);
            if (csv) fprintf(csv, "%d,%d", f + 1, i);
            for (int k = 0; k < hp.dim; k++) {
                if (!reg_read(&l, node_base + 16 * addr + 4u * (unsigned)k, &v)) goto done;
                if (csv) fprintf(csv, ",%.9g", fx_to_double(&sc->fmt, (fx_t)(int32_t)v));
                if (hex) fprintf(hex, "%s%0*x", k ? " " : "", digits, (unsigned)(v & mask));
            }
            if (csv) fputc('\n', csv);
            if (hex) fputc('\n', hex);
        }
    }
    if (!reg_read(&l, A_FRAMES, &v)) goto done;
    if ((int)v != frames) {
        fail(&l, "the board counted %u frames, not %d", v, frames);
        goto done;
    }
    ok = true;
done:
    if (l.fd >= 0) close(l.fd);
    free(writes);
    return ok;
}
