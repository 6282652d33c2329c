/*
 * scene.c - scene files: libinih does the INI syntax, this file the meaning.
 *
 * libinih (Debian's build) does not pass line numbers to the handler, so the line
 * reader below counts them: inih reads one line and then calls the handler for it,
 * so the count is the handler's line. The reader also checks section names, so an
 * empty unknown section is reported too, and rejects lines longer than inih's buffer.
 */
#include "scene.h"

#include <ini.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <ctype.h>
#include <string.h>

enum { S_SCENE, S_FORMAT, S_TIME, S_CHAIN, S_GRAPH, S_MOUSE, S_CONSTRAINTS, S_SPRINGS, S_GROUND, STRAND_EFFECT_SECTION_ENUM S_COUNT };
_Static_assert(S_COUNT == sizeof(((scene *)0)->section_lines) / sizeof(int), "one line slot per section");
static const char *const section_names[S_COUNT] = {
    "scene", "format", "time", "chain", "graph", "mouse", "constraints", "springs", "ground", STRAND_EFFECT_SECTION_NAMES
};

/* A vector value as written: 2 or 3 components, checked against dim after parsing. */
typedef struct {
    double v[3];
    int n;
    int line;
} vec_value;

typedef struct {
    int line;
    double off[3];
    int node;
    int n;
} node_offset;


typedef struct {
    scene *sc;
    FILE *fp;
    int line;
    int err_line; /* first error, 0 if none */
    char err[SCENE_ERR_LEN];
    int section_line[S_COUNT];
    /* values whose checks need the whole file */
    vec_value chain_start, chain_step, chain_end, box, velocity, prev_offset, origin;
    STRAND_EFFECT_PARSER_FIELDS
    int n_node_lines, cap_nodes;
    vec_value *node_values;
    int n_offsets, cap_offsets;
    node_offset *offsets;
    int cap_edges, cap_events, cap_pins;
    int *edge_lines, *event_lines;
    int n_pins;
    int *pins, *pin_lines;
    double scale;
    bool edge_rest_given_any;
    bool *edge_rest_given;
} parser;

static bool fail_at(parser *p, int line, const char *fmt, ...)
{
    if (p->err_line == 0) {
        va_list ap;
        int n = snprintf(p->err, sizeof p->err, "%s:%d: ", p->sc->path, line);
        va_start(ap, fmt);
        vsnprintf(p->err + n, sizeof p->err - (size_t)n, fmt, ap);
        va_end(ap);
        p->err_line = line;
    }
    return false;
}

#define FAIL(...) fail_at(p, p->line, __VA_ARGS__)

static int key_line(const parser *p, int section, const char *key)
{
    const scene *sc = p->sc;
    for (int i = 0; i < sc->n_keys; i++)
        if (sc->keys[i].section == section && strcmp(sc->keys[i].key, key) == 0) return sc->keys[i].line;
    return 0;
}

/* Line to blame for a cross-key problem: the key if present, else its section header, else 1. */
static int blame(const parser *p, int section, const char *key)
{
    int l = key ? key_line(p, section, key) : 0;
    if (!l) l = p->section_line[section];
    return l ? l : 1;
}

static void *xrealloc(void *ptr, size_t size)
{
    void *q = realloc(ptr, size);
    if (!q) {
        fprintf(stderr, "strand: out of memory\n");
        exit(1);
    }
    return q;
}

/* Room for one more item in arrays sharing the capacity *cap: returns true if they must grow to *cap. */
static bool need_room(int *cap, int count)
{
    if (count < *cap) return false;
    *cap = *cap ? *cap * 2 : 16;
    return true;
}

static void *grow(void *ptr, int *cap, int count, size_t elem)
{
    return need_room(cap, count) ? xrealloc(ptr, (size_t)*cap * elem) : ptr;
}

/* ---- value parsers: each reports "file:line: key: problem" ---- */

/* A number as the scene format writes it: [+-] digits [. digits] [e [+-] digits], with a digit
   before the exponent. strtod alone would also take hexadecimal (0x10), inf and nan. */
static bool is_decimal(const char *s)
{
    bool digits = false;
    if (*s == '+' || *s == '-') s++;
    for (; isdigit((unsigned char)*s); s++) digits = true;
    if (*s == '.')
        for (s++; isdigit((unsigned char)*s); s++) digits = true;
    if (!digits) return false;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-') s++;
        if (!isdigit((unsigned char)*s)) return false;
        while (isdigit((unsigned char)*s)) s++;
    }
    return *s == 0;
}

static bool parse_double(parser *p, const char *key, const char *s, double lo, double hi, double *out)
{
    char *end;
    double v;
    if (!*s) return FAIL("%s: missing value", key);
    if (!is_decimal(s)) return FAIL("%s: '%s' is not a decimal number", key, s);
    v = strtod(s, &end);
    if (end == s || *end || !isfinite(v)) return FAIL("%s: '%s' is out of the range of a double", key, s);
    if (v < lo || v > hi) return FAIL("%s: %g is out of range (%g..%g)", key, v, lo, hi);
    *out = v;
    return true;
}

static bool parse_int(parser *p, const char *key, const char *s, long lo, long hi, int *out)
{
    char *end;
    long v;
    if (!*s) return FAIL("%s: missing value", key);
    v = strtol(s, &end, 10);
    if (end == s || *end) return FAIL("%s: '%s' is not a whole number", key, s);
    if (v < lo || v > hi) return FAIL("%s: %ld is out of range (%ld..%ld)", key, v, lo, hi);
    *out = (int)v;
    return true;
}

/* Split on blanks into at most max words; returns the count or -1 if there are more. */
static int split_words(char *s, char **words, int max)
{
    int n = 0;
    for (char *tok = strtok(s, " \t"); tok; tok = strtok(NULL, " \t")) {
        if (n == max) return -1;
        words[n++] = tok;
    }
    return n;
}

static bool parse_numbers(parser *p, const char *key, const char *value, double *out, int min, int max, int *count)
{
    char buf[INI_MAX_LINE + 1];
    char *words[8];
    int n;
    if (!*value) return FAIL("%s: missing value", key);
    snprintf(buf, sizeof buf, "%s", value);
    n = split_words(buf, words, max);
    if (n < 0 || n < min)
        return min == max ? FAIL("%s: expected %d numbers", key, min) : FAIL("%s: expected %d to %d numbers", key, min, max);
    for (int i = 0; i < n; i++)
        if (!parse_double(p, key, words[i], -1e300, 1e300, &out[i])) return false;
    *count = n;
    return true;
}

static bool parse_vec(parser *p, const char *key, const char *value, vec_value *out)
{
    out->line = p->line;
    out->v[2] = 0;
    return parse_numbers(p, key, value, out->v, 2, 3, &out->n);
}

static bool parse_choice(parser *p, const char *key, const char *value, const char *const *choices, int *out)
{
    char list[160] = "";
    if (!*value) return FAIL("%s: missing value", key);
    for (int i = 0; choices[i]; i++) {
        if (strcmp(value, choices[i]) == 0) {
            *out = i;
            return true;
        }
        strcat(list, i ? ", " : "");
        strcat(list, choices[i]);
    }
    return FAIL("%s: '%s' is not one of: %s", key, value, list);
}

/* ---- the handler: one call per key ---- */

static int section_index(const char *name)
{
    for (int i = 0; i < S_COUNT; i++)
        if (strcmp(name, section_names[i]) == 0) return i;
    return -1;
}

static bool repeatable(int section, const char *key)
{
    return (section == S_GRAPH && (!strcmp(key, "node") || !strcmp(key, "edge") || !strcmp(key, "node_prev_offset") ||
                                   !strcmp(key, "pinned"))) ||
           (section == S_CHAIN && !strcmp(key, "pinned")) || (section == S_MOUSE && !strcmp(key, "event"));
}

static bool add_pins(parser *p, const char *key, const char *value)
{
    char buf[INI_MAX_LINE + 1];
    char *words[INI_MAX_LINE];
    int n;
    if (!*value) return FAIL("%s: missing value", key);
    snprintf(buf, sizeof buf, "%s", value);
    n = split_words(buf, words, INI_MAX_LINE);
    for (int i = 0; i < n; i++) {
        int idx;
        if (!parse_int(p, key, words[i], 0, SCENE_MAX_NODES - 1, &idx)) return false;
        if (need_room(&p->cap_pins, p->n_pins)) {
            p->pins = xrealloc(p->pins, (size_t)p->cap_pins * sizeof *p->pins);
            p->pin_lines = xrealloc(p->pin_lines, (size_t)p->cap_pins * sizeof *p->pin_lines);
        }
        p->pins[p->n_pins] = idx;
        p->pin_lines[p->n_pins++] = p->line;
    }
    return true;
}

static bool handle_graph_item(parser *p, const char *key, const char *value)
{
    scene *sc = p->sc;
    if (!strcmp(key, "node")) {
        if (p->n_node_lines >= SCENE_MAX_NODES) return FAIL("node: more than %d nodes", SCENE_MAX_NODES);
        p->node_values = grow(p->node_values, &p->cap_nodes, p->n_node_lines, sizeof *p->node_values);
        return parse_vec(p, key, value, &p->node_values[p->n_node_lines++]);
    }
    if (!strcmp(key, "node_prev_offset")) {
        double v[4];
        int n;
        if (!parse_numbers(p, key, value, v, 3, 4, &n)) return false;
        if (v[0] != floor(v[0]) || v[0] < 0) return FAIL("%s: node index '%g' is not a node number", key, v[0]);
        p->offsets = grow(p->offsets, &p->cap_offsets, p->n_offsets, sizeof *p->offsets);
        node_offset *o = &p->offsets[p->n_offsets++];
        o->line = p->line;
        o->node = v[0] > SCENE_MAX_NODES ? SCENE_MAX_NODES : (int)v[0];
        o->n = n - 1;
        o->off[0] = v[1], o->off[1] = v[2], o->off[2] = n == 4 ? v[3] : 0;
        return true;
    }
    /* edge = A B KIND [REST] */
    static const char *const kinds[] = {"rod", "strut", "spring", 0};
    char buf[INI_MAX_LINE + 1];
    char *w[5];
    int n, a, b, kind;
    double rest = 0;
    if (!*value) return FAIL("edge: missing value");
    snprintf(buf, sizeof buf, "%s", value);
    n = split_words(buf, w, 4);
    if (n < 3) return FAIL("edge: expected 'A B KIND [REST]'");
    if (!parse_int(p, "edge", w[0], 0, SCENE_MAX_NODES - 1, &a) || !parse_int(p, "edge", w[1], 0, SCENE_MAX_NODES - 1, &b) ||
        !parse_choice(p, "edge kind", w[2], kinds, &kind))
        return false;
    if (n == 4 && !parse_double(p, "edge rest", w[3], 1e-300, 1e300, &rest)) return false;
    if (a == b) return FAIL("edge: both ends are node %d", a);
    if (sc->n_edges >= SCENE_MAX_EDGES) return FAIL("edge: more than %d edges", SCENE_MAX_EDGES);
    if (need_room(&p->cap_edges, sc->n_edges)) {
        sc->edges = xrealloc(sc->edges, (size_t)p->cap_edges * sizeof *sc->edges);
        p->edge_lines = xrealloc(p->edge_lines, (size_t)p->cap_edges * sizeof *p->edge_lines);
        p->edge_rest_given = xrealloc(p->edge_rest_given, (size_t)p->cap_edges * sizeof *p->edge_rest_given);
    }
    sc->edges[sc->n_edges] = (scene_edge){a, b, (edge_kind)kind, rest, 0, 0, 0};
    p->edge_rest_given[sc->n_edges] = n == 4;
    p->edge_lines[sc->n_edges++] = p->line;
    return true;
}

static bool handle_mouse_event(parser *p, const char *value)
{
    scene *sc = p->sc;
    double v[5];
    int n;
    if (!parse_numbers(p, "event", value, v, 4, 5, &n)) return false;
    if (v[0] != floor(v[0]) || v[0] < 0 || v[0] > SCENE_MAX_FRAMES) return FAIL("event: frame '%g' is not a frame number", v[0]);
    if (v[n - 1] != 0 && v[n - 1] != 1) return FAIL("event: button must be 0 (up) or 1 (down), not %g", v[n - 1]);
    if (sc->n_events >= SCENE_MAX_EVENTS) return FAIL("event: more than %d events", SCENE_MAX_EVENTS);
    if (sc->n_events && v[0] < sc->events[sc->n_events - 1].frame)
        return FAIL("event: frame %g comes before the previous event's frame %d", v[0], sc->events[sc->n_events - 1].frame);
    if (need_room(&p->cap_events, sc->n_events)) {
        sc->events = xrealloc(sc->events, (size_t)p->cap_events * sizeof *sc->events);
        p->event_lines = xrealloc(p->event_lines, (size_t)p->cap_events * sizeof *p->event_lines);
    }
    mouse_event *e = &sc->events[sc->n_events];
    e->frame = (int)v[0];
    e->pos[0] = v[1], e->pos[1] = v[2], e->pos[2] = n == 5 ? v[3] : 0;
    e->down = v[n - 1] != 0;
    /* the component count (2 or 3) is checked against dim later, through event_lines' sign */
    p->event_lines[sc->n_events++] = n == 5 ? -p->line : p->line;
    return true;
}

static int handler(void *user, const char *section, const char *key, const char *value)
{
    parser *p = user;
    scene *sc = p->sc;
    int s = section_index(section);

    if (s < 0) return FAIL("unknown section [%s]", section); /* keys before any section */
    if (!repeatable(s, key)) {
        int prev = key_line(p, s, key);
        if (prev) return FAIL("%s: duplicate key (first given on line %d)", key, prev);
    }
    if (p->sc->n_keys < SCENE_MAX_KEYS && !key_line(p, s, key)) {
        scene *sc = p->sc;
        sc->keys[sc->n_keys].section = s;
        snprintf(sc->keys[sc->n_keys].key, sizeof sc->keys[sc->n_keys].key, "%s", key);
        sc->keys[sc->n_keys++].line = p->line;
    }

    STRAND_EFFECT_OTHER_KEYS /* the effects table's keys in the sections below ([time] damping) */
    switch (s) {
    case S_SCENE:
        if (!strcmp(key, "name")) {
            if (!*value) return FAIL("name: missing value");
            snprintf(sc->name, sizeof sc->name, "%s", value);
            return 1;
        }
        if (!strcmp(key, "y_axis")) {
            static const char *const c[] = {"up", "down", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->y_down = i == 1;
            return 1;
        }
        if (!strcmp(key, "dim")) {
            if (!parse_int(p, key, value, 2, 3, &sc->dim)) return 0;
            return 1;
        }
        break;
    case S_FORMAT:
        if (!strcmp(key, "number")) {
            static const char *const c[] = {"fixed", "double", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->number = (number_kind)i;
            return 1;
        }
        if (!strcmp(key, "width")) return parse_int(p, key, value, FX_MIN_WIDTH, FX_MAX_WIDTH, &sc->fmt.width);
        if (!strcmp(key, "frac")) return parse_int(p, key, value, 1, FX_MAX_WIDTH - 2, &sc->fmt.frac);
        if (!strcmp(key, "sqrt_bits")) return parse_int(p, key, value, 1, FX_MAX_WIDTH - 1, &sc->fmt.sqrt_bits);
        if (!strcmp(key, "div_bits")) return parse_int(p, key, value, 1, FX_MAX_WIDTH - 1, &sc->fmt.div_bits);
        if (!strcmp(key, "mantissa")) return parse_int(p, key, value, 0, FX_MAX_MANTISSA, &sc->fmt.mantissa);
        if (!strcmp(key, "pipe_steps")) return parse_int(p, key, value, 1, 4, &sc->pipe_steps);
        break;
    case S_TIME:
        if (!strcmp(key, "dt")) return parse_double(p, key, value, 1e-9, 1e6, &sc->dt);
        if (!strcmp(key, "frames")) return parse_int(p, key, value, 0, SCENE_MAX_FRAMES, &sc->frames);
        if (!strcmp(key, "substeps")) return parse_int(p, key, value, 1, SCENE_MAX_SUBSTEPS, &sc->substeps);
        if (!strcmp(key, "iterations")) return parse_int(p, key, value, 1, SCENE_MAX_ITERATIONS, &sc->iterations);
        if (!strcmp(key, "integrator")) {
            static const char *const c[] = {"verlet", "euler", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->integrator = (integrator_kind)i;
            return 1;
        }
        break;
    case S_CHAIN:
    case S_GRAPH:
        if (!strcmp(key, "units")) return parse_int(p, key, value, 1, SCENE_MAX_NODES, &sc->units);
        if (!strcmp(key, "nodes_per_unit")) return parse_int(p, key, value, 1, SCENE_MAX_NODES, &sc->nodes_per_unit);
        if (!strcmp(key, "mass")) return parse_double(p, key, value, 1e-12, 1e12, &sc->mass);
        if (!strcmp(key, "pinned")) return add_pins(p, key, value);
        if (!strcmp(key, "velocity")) return parse_vec(p, key, value, &p->velocity);
        if (!strcmp(key, "prev_offset")) return parse_vec(p, key, value, &p->prev_offset);
        if (s == S_CHAIN) {
            if (!strcmp(key, "nodes")) return parse_int(p, key, value, 1, SCENE_MAX_NODES, &sc->n_nodes);
            if (!strcmp(key, "start")) return parse_vec(p, key, value, &p->chain_start);
            if (!strcmp(key, "step")) return parse_vec(p, key, value, &p->chain_step);
            if (!strcmp(key, "end")) return parse_vec(p, key, value, &p->chain_end);
            if (!strcmp(key, "rest")) return parse_double(p, key, value, 1e-300, 1e300, &sc->chain_rest);
        } else {
            if (!strcmp(key, "node") || !strcmp(key, "edge") || !strcmp(key, "node_prev_offset"))
                return handle_graph_item(p, key, value);
            if (!strcmp(key, "scale")) return parse_double(p, key, value, 1e-12, 1e12, &p->scale);
            if (!strcmp(key, "origin")) return parse_vec(p, key, value, &p->origin);
        }
        break;
    case S_MOUSE:
        if (!strcmp(key, "mode")) {
            static const char *const c[] = {"impulse", "grab", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->mouse = (mouse_mode)i;
            return 1;
        }
        if (!strcmp(key, "box")) return parse_vec(p, key, value, &p->box);
        if (!strcmp(key, "impulse")) return parse_double(p, key, value, -1e12, 1e12, &sc->mouse_impulse);
        if (!strcmp(key, "event")) return handle_mouse_event(p, value);
        break;
    case S_CONSTRAINTS:
        if (!strcmp(key, "rule")) {
            static const char *const c[] = {"centred", "pairwise", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->rule = (constraint_rule)i;
            return 1;
        }
        if (!strcmp(key, "order")) {
            static const char *const c[] = {"serial", "redblack", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->order = (constraint_order)i;
            return 1;
        }
        if (!strcmp(key, "projection")) {
            static const char *const c[] = {"current", "previous", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->projection = (constraint_projection)i;
            return 1;
        }
        break;
    case S_SPRINGS:
        if (!strcmp(key, "ks")) return parse_double(p, key, value, 0, 1e12, &sc->ks);
        if (!strcmp(key, "kd")) return parse_double(p, key, value, 0, 1e12, &sc->kd);
        if (!strcmp(key, "damper_velocity")) {
            static const char *const c[] = {"per_second", "per_step", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->kd_per_step = i == 1;
            return 1;
        }
        break;
    case S_GROUND:
        if (!strcmp(key, "normal")) {
            static const char *const c[] = {"+x", "-x", "+y", "-y", "+z", "-z", 0};
            int i;
            if (!parse_choice(p, key, value, c, &i)) return 0;
            sc->ground_axis = i / 2;
            sc->ground_sign = i % 2 ? -1 : 1;
            return 1;
        }
        if (!strcmp(key, "level")) return parse_double(p, key, value, -1e12, 1e12, &sc->ground_level);
        if (!strcmp(key, "radius")) return parse_double(p, key, value, 0, 1e12, &sc->ground_radius);
        if (!strcmp(key, "friction")) return parse_double(p, key, value, 0, 1, &sc->ground_friction);
        break;
    STRAND_EFFECT_PARSE_CASES /* the effects table's sections */
    }
    return FAIL("unknown key '%s' in [%s]", key, section);
}

/* The line reader: counts lines, checks section headers, rejects over-long lines and
   NUL bytes (fgets and inih's string functions would silently stop at one). */
static char *reader(char *str, int num, void *stream)
{
    parser *p = stream;
    size_t len = 0;
    int ch = EOF;
    char *s;
    while (len + 1 < (size_t)num && (ch = getc(p->fp)) != EOF) {
        if (ch == '\0') {
            fail_at(p, p->line + 1, "the line contains a NUL byte: a scene is text");
            return NULL;
        }
        str[len++] = (char)ch;
        if (ch == '\n') break;
    }
    if (len == 0) return NULL;
    str[len] = 0;
    p->line++;
    if (str[len - 1] != '\n' && len + 1 >= (size_t)num) {
        int next = getc(p->fp);
        if (next != EOF && next != '\n') {
            fail_at(p, p->line, "line is longer than %d characters", num - 1);
            return NULL;
        }
    }
    for (s = str; *s == ' ' || *s == '\t'; s++)
        ;
    if (*s == '[') {
        char name[64];
        size_t n = strcspn(s + 1, "]");
        int idx;
        const char *after;
        if (s[1 + n] != ']') return str; /* let inih report the syntax error */
        snprintf(name, sizeof name, "%.*s", (int)(n < 63 ? n : 63), s + 1);
        /* inih ignores what follows the ']': only blanks and a comment may */
        for (after = s + 2 + n; *after == ' ' || *after == '\t' || *after == '\r'; after++)
            ;
        if (*after && *after != '\n' && *after != ';' && *after != '#') {
            fail_at(p, p->line, "unexpected text after [%s]: only a comment may follow a section header", name);
            return NULL;
        }
        idx = section_index(name);
        if (idx < 0) {
            fail_at(p, p->line, "unknown section [%s]", name);
        } else if (p->section_line[idx]) {
            fail_at(p, p->line, "section [%s] appears twice (first on line %d)", name, p->section_line[idx]);
        } else {
            p->section_line[idx] = p->line;
        }
    }
    return str;
}

/* ---- checks that need the whole file ---- */

static bool check_vec(parser *p, const vec_value *v, const char *key)
{
    if (v->n && v->n != p->sc->dim)
        return fail_at(p, v->line, "%s: expected %d numbers for a %dD scene, got %d", key, p->sc->dim, p->sc->dim, v->n);
    return true;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static bool alloc_nodes(scene *sc)
{
    sc->pos = calloc((size_t)sc->n_nodes, sizeof *sc->pos);
    sc->prev = calloc((size_t)sc->n_nodes, sizeof *sc->prev);
    sc->pinned = calloc((size_t)sc->n_nodes, sizeof *sc->pinned);
    return sc->pos && sc->prev && sc->pinned;
}

static bool build_chain(parser *p)
{
    scene *sc = p->sc;
    int n = sc->units * sc->nodes_per_unit;
    if (!key_line(p, S_CHAIN, "units")) return fail_at(p, blame(p, S_CHAIN, NULL), "[chain] needs 'units'");
    if (!key_line(p, S_CHAIN, "nodes_per_unit")) return fail_at(p, blame(p, S_CHAIN, NULL), "[chain] needs 'nodes_per_unit'");
    if (n > SCENE_MAX_NODES) return fail_at(p, blame(p, S_CHAIN, "nodes_per_unit"), "units x nodes_per_unit = %d exceeds %d nodes", n, SCENE_MAX_NODES);
    if (key_line(p, S_CHAIN, "nodes") && sc->n_nodes != n)
        return fail_at(p, blame(p, S_CHAIN, "nodes"), "nodes = %d but units x nodes_per_unit = %d x %d = %d", sc->n_nodes,
                       sc->units, sc->nodes_per_unit, n);
    sc->n_nodes = n;
    if (!p->chain_start.n) return fail_at(p, blame(p, S_CHAIN, NULL), "[chain] needs 'start'");
    if (p->chain_step.n && p->chain_end.n)
        return fail_at(p, blame(p, S_CHAIN, "end"), "give 'step' or 'end', not both");
    if (!p->chain_step.n && !p->chain_end.n) return fail_at(p, blame(p, S_CHAIN, NULL), "[chain] needs 'step' or 'end'");
    if (!check_vec(p, &p->chain_start, "start") || !check_vec(p, &p->chain_step, "step") || !check_vec(p, &p->chain_end, "end"))
        return false;
    for (int k = 0; k < 3; k++) {
        sc->chain_start[k] = p->chain_start.v[k];
        if (p->chain_step.n)
            sc->chain_step[k] = p->chain_step.v[k];
        else
            sc->chain_step[k] = n > 1 ? (p->chain_end.v[k] - p->chain_start.v[k]) / (n - 1) : 0;
    }
    if (!key_line(p, S_CHAIN, "rest")) {
        double zero[3] = {0, 0, 0};
        sc->chain_rest = dist3(sc->chain_step, zero);
        if (sc->chain_rest == 0 && n > 1) return fail_at(p, blame(p, S_CHAIN, NULL), "nodes start on one point: give 'rest'");
    }
    if (!alloc_nodes(sc)) return fail_at(p, 1, "out of memory");
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) sc->pos[i][k] = sc->chain_start[k] + i * sc->chain_step[k];
    /* neighbours are implied: one edge per segment and per linking effect */
    int links = (sc->en_constraints ? 1 : 0) + (sc->en_springs ? 1 : 0);
    if (n > 1 && links) {
        sc->n_edges = (n - 1) * links;
        sc->edges = calloc((size_t)sc->n_edges, sizeof *sc->edges);
        if (!sc->edges) return fail_at(p, 1, "out of memory");
        int e = 0;
        if (sc->en_constraints)
            for (int i = 0; i + 1 < n; i++) sc->edges[e++] = (scene_edge){i, i + 1, EDGE_ROD, sc->chain_rest, 0, 0, 0};
        if (sc->en_springs)
            for (int i = 0; i + 1 < n; i++) sc->edges[e++] = (scene_edge){i, i + 1, EDGE_SPRING, sc->chain_rest, 0, 0, 0};
    }
    return true;
}

static bool build_graph(parser *p)
{
    scene *sc = p->sc;
    double scale = key_line(p, S_GRAPH, "scale") ? p->scale : 1.0;
    int n = p->n_node_lines;
    if (n == 0) return fail_at(p, blame(p, S_GRAPH, NULL), "[graph] lists no 'node'");
    if (!check_vec(p, &p->origin, "origin")) return false;
    for (int i = 0; i < n; i++)
        if (!check_vec(p, &p->node_values[i], "node")) return false;
    if (!key_line(p, S_GRAPH, "units")) sc->units = 1;
    if (!key_line(p, S_GRAPH, "nodes_per_unit")) sc->nodes_per_unit = n / sc->units;
    if (sc->units * sc->nodes_per_unit != n)
        return fail_at(p, blame(p, S_GRAPH, key_line(p, S_GRAPH, "nodes_per_unit") ? "nodes_per_unit" : "units"),
                       "the graph lists %d nodes but units x nodes_per_unit = %d x %d = %d", n, sc->units, sc->nodes_per_unit,
                       sc->units * sc->nodes_per_unit);
    sc->n_nodes = n;
    if (!alloc_nodes(sc)) return fail_at(p, 1, "out of memory");
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) sc->pos[i][k] = p->node_values[i].v[k] * scale + p->origin.v[k];
    for (int e = 0; e < sc->n_edges; e++) {
        scene_edge *ed = &sc->edges[e];
        int line = p->edge_lines[e];
        if (ed->a >= n || ed->b >= n)
            return fail_at(p, line, "edge: node %d does not exist (the graph has nodes 0..%d)", ed->a >= n ? ed->a : ed->b, n - 1);
        if (!p->edge_rest_given[e]) {
            ed->rest = dist3(sc->pos[ed->a], sc->pos[ed->b]);
            if (ed->rest == 0) return fail_at(p, line, "edge: nodes %d and %d start on one point: give a rest length", ed->a, ed->b);
        }
        if ((ed->kind == EDGE_ROD || ed->kind == EDGE_STRUT) && !sc->en_constraints)
            return fail_at(p, line, "edge: a %s needs the [constraints] effect", ed->kind == EDGE_ROD ? "rod" : "strut");
        if (ed->kind == EDGE_SPRING && !sc->en_springs) return fail_at(p, line, "edge: a spring needs the [springs] effect");
    }
    return true;
}

/* A fixed-point scene: every value must fit the format; blame the line that gave it. */
static bool fits_at(parser *p, double v, int line, const char *what)
{
    const fx_format *fmt = &p->sc->fmt;
    double range = ldexp(1.0, fmt->width - fmt->frac - 1);
    if (fx_fits(fmt, v)) return true;
    return fail_at(p, line ? line : 1, "%s = %g does not fit Q%d.%d (range -%g..%g)", what, v, fmt->width - fmt->frac, fmt->frac, range,
                   range);
}

static bool check_fits(parser *p)
{
    scene *sc = p->sc;
    bool chain = sc->body == BODY_CHAIN;
    int pos_line = chain ? blame(p, S_CHAIN, key_line(p, S_CHAIN, "end") ? "end" : "step") : 0;
    int prev_line = blame(p, chain ? S_CHAIN : S_GRAPH, key_line(p, chain ? S_CHAIN : S_GRAPH, "velocity") ? "velocity" : "prev_offset");
    for (int i = 0; i < sc->n_nodes; i++)
        for (int k = 0; k < sc->dim; k++) {
            if (!fits_at(p, sc->pos[i][k], chain ? (i ? pos_line : blame(p, S_CHAIN, "start")) : p->node_values[i].line, "a node position"))
                return false;
            if (!fits_at(p, sc->prev[i][k] - sc->pos[i][k], prev_line, "a node's initial motion")) return false;
        }
    for (int e = 0; e < sc->n_edges; e++)
        if (!fits_at(p, sc->edges[e].rest, chain ? blame(p, S_CHAIN, "rest") : p->edge_lines[e], "a rest length")) return false;
    for (int k = 0; k < sc->dim; k++) {
        if (chain && !fits_at(p, sc->chain_step[k], pos_line, "the chain step")) return false;
        if (sc->en_mouse && !fits_at(p, sc->mouse_box[k], p->box.line, "the mouse box")) return false;
        for (int e = 0; e < sc->n_events; e++)
            if (!fits_at(p, sc->events[e].pos[k], abs(p->event_lines[e]), "a mouse position")) return false;
    }
    if (sc->en_mouse && !fits_at(p, sc->mouse_impulse, blame(p, S_MOUSE, "impulse"), "the mouse impulse")) return false;
    if (sc->en_ground &&
        !fits_at(p, sc->ground_level + sc->ground_sign * sc->ground_radius, blame(p, S_GROUND, "level"), "the ground boundary"))
        return false;
    return true;
}

static bool finish(parser *p)
{
    scene *sc = p->sc;
    const char *msg;

    if (!p->section_line[S_TIME]) return fail_at(p, 1, "the scene has no [time] section");
    if (!key_line(p, S_TIME, "dt")) return fail_at(p, blame(p, S_TIME, NULL), "[time] needs 'dt'");
    if (p->section_line[S_CHAIN] && p->section_line[S_GRAPH])
        return fail_at(p, p->section_line[S_CHAIN] > p->section_line[S_GRAPH] ? p->section_line[S_CHAIN] : p->section_line[S_GRAPH],
                       "a scene has one body: [chain] or [graph], not both");
    if (!p->section_line[S_CHAIN] && !p->section_line[S_GRAPH]) return fail_at(p, 1, "the scene has no body: add [chain] or [graph]");
    sc->body = p->section_line[S_GRAPH] ? BODY_GRAPH : BODY_CHAIN;

    /* format */
    if (!key_line(p, S_FORMAT, "sqrt_bits")) sc->fmt.sqrt_bits = sc->fmt.width - 1;
    if (!key_line(p, S_FORMAT, "div_bits")) sc->fmt.div_bits = sc->fmt.width - 1;
    if (!key_line(p, S_FORMAT, "pipe_steps")) sc->pipe_steps = 2; /* the pipelined builds' default: make synth measures 1, 2 and 4 */
    if ((msg = fx_format_check(&sc->fmt))) {
        const char *key = sc->fmt.frac > sc->fmt.width - 2 ? "frac" : sc->fmt.sqrt_bits > sc->fmt.width - 1 ? "sqrt_bits"
                          : sc->fmt.div_bits > sc->fmt.width - 1 ? "div_bits" : "mantissa";
        if (!key_line(p, S_FORMAT, key)) key = "width"; /* a default no longer fits the width */
        return fail_at(p, blame(p, S_FORMAT, key), "%s (width = %d, frac = %d)", msg, sc->fmt.width, sc->fmt.frac);
    }

    /* effects are on when named */
    sc->en_mouse = p->section_line[S_MOUSE] != 0;
    sc->en_constraints = p->section_line[S_CONSTRAINTS] != 0;
    sc->en_springs = p->section_line[S_SPRINGS] != 0;
    sc->en_ground = p->section_line[S_GROUND] != 0;

    if (sc->en_springs && !key_line(p, S_SPRINGS, "ks")) return fail_at(p, blame(p, S_SPRINGS, NULL), "[springs] needs 'ks'");
    if (sc->en_ground) {
        if (!key_line(p, S_GROUND, "normal")) return fail_at(p, blame(p, S_GROUND, NULL), "[ground] needs 'normal'");
        if (sc->ground_axis >= sc->dim) return fail_at(p, blame(p, S_GROUND, "normal"), "normal: a %dD scene has no z axis", sc->dim);
    }
    if (sc->en_mouse) {
        if (!p->box.n) return fail_at(p, blame(p, S_MOUSE, NULL), "[mouse] needs 'box'");
        if (!check_vec(p, &p->box, "box")) return false;
        for (int k = 0; k < sc->dim; k++)
            if (p->box.v[k] <= 0) return fail_at(p, p->box.line, "box: half-widths must be positive");
        memcpy(sc->mouse_box, p->box.v, sizeof sc->mouse_box);
        if (sc->mouse == MOUSE_IMPULSE && !key_line(p, S_MOUSE, "impulse"))
            return fail_at(p, blame(p, S_MOUSE, NULL), "[mouse] mode = impulse needs 'impulse'");
        for (int e = 0; e < sc->n_events; e++) {
            int line = p->event_lines[e] < 0 ? -p->event_lines[e] : p->event_lines[e];
            int n = p->event_lines[e] < 0 ? 3 : 2;
            if (n != sc->dim) return fail_at(p, line, "event: expected frame, %d coordinates and the button", sc->dim);
        }
    }

    if (sc->body == BODY_CHAIN) {
        if (!build_chain(p)) return false;
    } else {
        if (sc->en_constraints && sc->rule == RULE_CENTRED && key_line(p, S_CONSTRAINTS, "rule"))
            return fail_at(p, blame(p, S_CONSTRAINTS, "rule"), "rule: the centred rule walks a chain; a graph uses 'pairwise'");
        if (sc->en_constraints) sc->rule = RULE_PAIRWISE;
        if (!build_graph(p)) return false;
    }

    for (int i = 0; i < p->n_pins; i++) {
        if (p->pins[i] >= sc->n_nodes)
            return fail_at(p, p->pin_lines[i], "pinned: node %d does not exist (the body has nodes 0..%d)", p->pins[i], sc->n_nodes - 1);
        sc->pinned[p->pins[i]] = true;
    }

    STRAND_EFFECT_FINISH /* the effects table's: on when named, their keys checked */
    {
        scene_consts c;
        scene_constants(sc, &c);
        STRAND_EFFECT_CHECK_CONSTS(c)
    }

    if (sc->integrator == INTEGRATOR_EULER) {
        int line = blame(p, S_TIME, "integrator");
        if (sc->en_constraints) return fail_at(p, line, "integrator: euler cannot project [constraints]; use springs or verlet");
        if (sc->en_ground) return fail_at(p, line, "integrator: euler does not support [ground]; use verlet");
        if (sc->en_mouse) return fail_at(p, line, "integrator: euler does not support [mouse]; use verlet");
    }

    /* previous positions: at rest, then the whole-body velocity and offsets */
    if (!check_vec(p, &p->velocity, "velocity") || !check_vec(p, &p->prev_offset, "prev_offset")) return false;
    for (int o = 0; o < p->n_offsets; o++) {
        node_offset *off = &p->offsets[o];
        if (off->n != sc->dim) return fail_at(p, off->line, "node_prev_offset: expected a node index and %d numbers", sc->dim);
        if (off->node >= sc->n_nodes) return fail_at(p, off->line, "node_prev_offset: node %d does not exist", off->node);
    }
    for (int i = 0; i < sc->n_nodes; i++)
        for (int k = 0; k < 3; k++) sc->prev[i][k] = sc->pos[i][k] - p->velocity.v[k] * scene_h(sc) + p->prev_offset.v[k];
    for (int o = 0; o < p->n_offsets; o++)
        for (int k = 0; k < 3; k++) sc->prev[p->offsets[o].node][k] += p->offsets[o].off[k];
    for (int i = 0; i < sc->n_nodes; i++)
        if (sc->pinned[i]) memcpy(sc->prev[i], sc->pos[i], sizeof sc->prev[i]);

    if (sc->number == NUMBER_FIXED && !check_fits(p)) return false;
    for (int e = 0; e < sc->n_edges; e++) {
        sc->edges[e].src = e;
        sc->edges[e].line = sc->body == BODY_CHAIN ? blame(p, S_CHAIN, "rest") : p->edge_lines[e];
    }
    if (scene_set_order(sc, sc->order, p->err) < 0) {
        /* the message names no line: the order key's (or the first line) */
        char msg[SCENE_ERR_LEN];
        snprintf(msg, sizeof msg, "%s", p->err);
        return fail_at(p, blame(p, S_CONSTRAINTS, "order"), "%s", msg);
    }
    return true;
}

bool scene_load(scene *sc, const char *path, char *err)
{
    parser p;
    int rc;
    memset(sc, 0, sizeof *sc);
    memset(&p, 0, sizeof p);
    p.sc = sc;
    snprintf(sc->path, sizeof sc->path, "%s", path);
    {
        const char *base = strrchr(path, '/');
        snprintf(sc->name, sizeof sc->name, "%s", base ? base + 1 : path);
        char *dot = strrchr(sc->name, '.');
        if (dot) *dot = 0;
    }
    sc->dim = 2;
    sc->number = NUMBER_FIXED;
    sc->fmt = (fx_format){32, 16, 0, 0, 0};
    sc->frames = 100;
    sc->substeps = 1;
    sc->iterations = 1;
    sc->mass = 1;
    sc->units = 1;
    sc->ground_friction = 1;

    p.fp = fopen(path, "r");
    if (!p.fp) {
        snprintf(err, SCENE_ERR_LEN, "%s:0: cannot open the scene file", path);
        return false;
    }
    rc = ini_parse_stream(reader, &p, handler, &p);
    fclose(p.fp);
    if (rc > 0 && (p.err_line == 0 || rc < p.err_line)) {
        p.err_line = 0;
        fail_at(&p, rc, "syntax error: expected '[section]', 'key = value' or a comment");
    } else if (rc < 0) {
        fail_at(&p, 1, "cannot read the scene file");
    }
    if (!p.err_line) finish(&p);
    memcpy(sc->section_lines, p.section_line, sizeof sc->section_lines);

    free(p.node_values);
    free(p.offsets);
    free(p.edge_lines);
    free(p.event_lines);
    free(p.pins);
    free(p.pin_lines);
    free(p.edge_rest_given);
    if (p.err_line) {
        snprintf(err, SCENE_ERR_LEN, "%s", p.err);
        scene_free(sc);
        return false;
    }
    return true;
}

void scene_free(scene *sc)
{
    free(sc->pos);
    free(sc->prev);
    free(sc->pinned);
    free(sc->edges);
    free(sc->events);
    sc->pos = sc->prev = NULL;
    sc->pinned = NULL;
    sc->edges = NULL;
    sc->events = NULL;
}

const char *scene_effects_string(const scene *sc, char *buf, size_t len)
{
    snprintf(buf, len, STRAND_EFFECT_NAMES_FMT "%s%s%s%s", STRAND_EFFECT_NAMES_ARGS(sc), sc->en_mouse ? (sc->mouse == MOUSE_GRAB ? "mouse-grab " : "mouse-impulse ") : "",
             sc->en_constraints ? (sc->rule == RULE_CENTRED ? "centred " : "pairwise ") : "", sc->en_springs ? "springs " : "",
             sc->en_ground ? "ground " : "");
    size_t n = strlen(buf);
    if (n) buf[n - 1] = 0;
    else snprintf(buf, len, "none");
    return buf;
}

const char *scene_check_format(const scene *sc, const fx_format *fmt, char *buf, size_t len)
{
    double range = ldexp(1.0, fmt->width - fmt->frac - 1);
#define CHECK(val, what)                                                                                                        \
    do {                                                                                                                        \
        if (!fx_fits(fmt, (val))) {                                                                                             \
            snprintf(buf, len, "%s = %g does not fit Q%d.%d (range -%g..%g)", what, (double)(val), fmt->width - fmt->frac, fmt->frac, \
                     range, range);                                                                                             \
            return buf;                                                                                                         \
        }                                                                                                                       \
    } while (0)
    for (int i = 0; i < sc->n_nodes; i++)
        for (int k = 0; k < sc->dim; k++) {
            CHECK(sc->pos[i][k], "a node position");
            CHECK(sc->prev[i][k], "a node's previous position");
        }
    for (int e = 0; e < sc->n_edges; e++) CHECK(sc->edges[e].rest, "a rest length");
    for (int k = 0; k < sc->dim; k++) {
        CHECK(sc->chain_step[k], "the chain step");
        if (sc->en_mouse) CHECK(sc->mouse_box[k], "the mouse box");
        for (int e = 0; e < sc->n_events; e++) CHECK(sc->events[e].pos[k], "a mouse position");
    }
    if (sc->en_mouse) CHECK(sc->mouse_impulse, "the mouse impulse");
    if (sc->en_ground) CHECK(sc->ground_level + sc->ground_sign * sc->ground_radius, "the ground boundary");
#undef CHECK
    return NULL;
}

int scene_section_line(const scene *sc, const char *section)
{
    int i = section_index(section);
    return i >= 0 && sc->section_lines[i] ? sc->section_lines[i] : 1;
}

int scene_key_line(const scene *sc, const char *section, const char *key)
{
    int s = section_index(section);
    for (int i = 0; i < sc->n_keys; i++)
        if (sc->keys[i].section == s && strcmp(sc->keys[i].key, key) == 0) return sc->keys[i].line;
    return scene_section_line(sc, section);
}

void scene_constants(const scene *sc, scene_consts *c)
{
    double h = scene_h(sc), m = sc->mass;
    bool verlet = sc->integrator == INTEGRATOR_VERLET;
    /* Springs: Verlet adds F h^2 / m to the position; velocity is x - x- (per substep). */
    if (verlet) {
        c->ks = sc->ks * h * h / m;
        c->kd = sc->kd_per_step ? sc->kd * h * h / m : sc->kd * h / m;
    } else {
        c->ks = sc->ks / m;
        c->kd = sc->kd_per_step ? sc->kd * h / m : sc->kd / m;
    }
    c->impulse = sc->mouse_impulse;
    c->friction = 1.0 - sc->ground_friction;
    c->ground = sc->ground_level + sc->ground_sign * sc->ground_radius;
    c->h = h;
    STRAND_EFFECT_CONSTANTS /* the effects table's */
}

void scene_mouse_at(const scene *sc, int frame, double pos[3], bool *down)
{
    pos[0] = pos[1] = pos[2] = 0;
    *down = false;
    for (int e = 0; e < sc->n_events && sc->events[e].frame <= frame; e++) {
        memcpy(pos, sc->events[e].pos, 3 * sizeof(double));
        *down = sc->events[e].down;
    }
}

static bool is_constraint(const scene_edge *e) { return e->kind != EDGE_SPRING; }

/* Sorting key: constraint edges by (colour, scene order), springs after them in scene order. */
static int edge_order_cmp(const void *a, const void *b)
{
    const scene_edge *x = a, *y = b;
    int kx = !is_constraint(x), ky = !is_constraint(y);
    if (kx != ky) return kx - ky;
    if (x->colour != y->colour) return x->colour - y->colour;
    return x->src - y->src;
}

static int src_cmp(const void *a, const void *b) { return ((const scene_edge *)a)->src - ((const scene_edge *)b)->src; }

int scene_set_order(scene *sc, constraint_order order, char *err)
{
    sc->order = order;
    sc->n_colours = 1;
    if (sc->n_edges == 0) return 1;
    /* back to the scene's order; the colours are made in it */
    qsort(sc->edges, (size_t)sc->n_edges, sizeof *sc->edges, src_cmp);
    for (int e = 0; e < sc->n_edges; e++) sc->edges[e].colour = 0;
    if (order == ORDER_SERIAL) return 1;
    uint64_t *used = calloc((size_t)sc->n_nodes, sizeof *used); /* colours at each node */
    if (!used) {
        snprintf(err, SCENE_ERR_LEN, "out of memory");
        return -1;
    }
    int colours = 1;
    for (int e = 0; e < sc->n_edges; e++) {
        scene_edge *ed = &sc->edges[e];
        if (!is_constraint(ed)) continue;
        uint64_t taken = used[ed->a] | used[ed->b];
        int c = 0;
        while (c < SCENE_MAX_COLOURS && (taken >> c & 1)) c++;
        if (c == SCENE_MAX_COLOURS) {
            snprintf(err, SCENE_ERR_LEN, "order = redblack: the edge %d-%d needs a colour beyond %d (a node with that many constraint edges)",
                     ed->a, ed->b, SCENE_MAX_COLOURS - 1);
            free(used);
            return -1;
        }
        ed->colour = c;
        used[ed->a] |= 1ull << c;
        used[ed->b] |= 1ull << c;
        if (c + 1 > colours) colours = c + 1;
    }
    free(used);
    qsort(sc->edges, (size_t)sc->n_edges, sizeof *sc->edges, edge_order_cmp);
    sc->n_colours = colours;
    return colours;
}
