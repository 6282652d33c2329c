/* scene_edit.c - a scene file with some of its keys set (scene.h scene_edit; `strand set`).
 *
 * The scripts derive scenes from the shipped ones (another rule, format, substep count or
 * mantissa) through this one writer, so that the C parser's rules say what a key is and
 * where it goes, and a bad value is refused with the parser's own message. The file is
 * edited as text, so its comments and layout stay: a key that is there has its line
 * replaced, one that is not is added at the end of its section, a section that is not
 * there is added at the end of the file. */
#include "scene.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char *text;
    int origin; /* > 0: the line of the input file; < 0: -(1 + the assignment that wrote it) */
} edit_line;

typedef struct {
    edit_line *lines;
    int n, cap;
} edit_file;

static bool push_line(edit_file *f, int at, char *text, int origin)
{
    if (f->n == f->cap) {
        int cap = f->cap ? 2 * f->cap : 64;
        edit_line *l = realloc(f->lines, (size_t)cap * sizeof *l);
        if (!l) return false;
        f->lines = l;
        f->cap = cap;
    }
    memmove(&f->lines[at + 1], &f->lines[at], (size_t)(f->n - at) * sizeof *f->lines);
    f->lines[at] = (edit_line){text, origin};
    f->n++;
    return true;
}

static void free_file(edit_file *f)
{
    for (int i = 0; i < f->n; i++) free(f->lines[i].text);
    free(f->lines);
}

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

static const char *skip_space(const char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    return s;
}

/* The section a header line names (into name), or false for any other line. */
static bool header_of(const char *line, char *name, size_t len)
{
    const char *s = skip_space(line);
    if (*s != '[') return false;
    const char *end = strchr(s, ']');
    if (!end) return false;
    s = skip_space(s + 1);
    size_t n = (size_t)(end - s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) n--;
    if (n >= len) n = len - 1;
    memcpy(name, s, n);
    name[n] = 0;
    return true;
}

/* Does this line set `key` (a key = value line, not a comment)? */
static bool sets_key(const char *line, const char *key)
{
    const char *s = skip_space(line);
    if (*s == ';' || *s == '#' || *s == '[' || !*s) return false;
    size_t n = strlen(key);
    if (strncmp(s, key, n)) return false;
    s = skip_space(s + n);
    return *s == '=';
}

static bool is_blank_or_comment(const char *line)
{
    const char *s = skip_space(line);
    return !*s || *s == ';' || *s == '#';
}

static bool word_ok(const char *s, size_t n)
{
    if (n == 0) return false;
    for (size_t i = 0; i < n; i++)
        if (!isalnum((unsigned char)s[i]) && s[i] != '_') return false;
    return true;
}

/* Read path into f, one line an entry (no newline kept). */
static bool read_file(const char *path, edit_file *f, char *err)
{
    FILE *fp = fopen(path, "r");
    if (!fp) {
        snprintf(err, SCENE_ERR_LEN, "%s:0: cannot open the scene file (%s)", path, strerror(errno));
        return false;
    }
    char buf[4096];
    int line = 0;
    bool ok = true;
    while (ok && fgets(buf, sizeof buf, fp)) {
        size_t n = strlen(buf);
        line++;
        if (n == sizeof buf - 1 && buf[n - 1] != '\n') {
            snprintf(err, SCENE_ERR_LEN, "%s:%d: line longer than %d characters", path, line, (int)sizeof buf - 2);
            ok = false;
            break;
        }
        while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == '\r')) buf[--n] = 0;
        char *copy = dup_string(buf);
        ok = copy && push_line(f, f->n, copy, line);
        if (!ok) free(copy);
    }
    fclose(fp);
    if (!ok && !err[0]) snprintf(err, SCENE_ERR_LEN, "%s:0: out of memory", path);
    return ok;
}

/* One assignment SECTION.KEY=VALUE applied to f; false with a message in err. */
static bool apply(edit_file *f, const char *in, int index, const char *assign, char *err)
{
    const char *dot = strchr(assign, '.'), *eq = strchr(assign, '=');
    if (!dot || !eq || dot > eq || !word_ok(assign, (size_t)(dot - assign)) || !word_ok(dot + 1, (size_t)(eq - dot - 1))) {
        snprintf(err, SCENE_ERR_LEN, "'%s': want SECTION.KEY=VALUE (letters, digits and '_' in SECTION and KEY)", assign);
        return false;
    }
    char section[64], key[64], name[64];
    snprintf(section, sizeof section, "%.*s", (int)(dot - assign), assign);
    snprintf(key, sizeof key, "%.*s", (int)(eq - dot - 1), dot + 1);
    const char *value = skip_space(eq + 1);
    size_t vn = strlen(value);
    while (vn > 0 && (value[vn - 1] == ' ' || value[vn - 1] == '\t')) vn--;
    if (vn == 0 || strcspn(value, ";#\n\r") < vn) {
        snprintf(err, SCENE_ERR_LEN, "'%s': the value is empty or holds a comment character or a line break", assign);
        return false;
    }
    char *text = malloc(strlen(key) + vn + 4);
    if (!text) {
        snprintf(err, SCENE_ERR_LEN, "out of memory");
        return false;
    }
    sprintf(text, "%s = %.*s", key, (int)vn, value);

    int start = -1, found = 0;
    for (int i = 0; i < f->n; i++)
        if (header_of(f->lines[i].text, name, sizeof name) && !strcmp(name, section)) {
            start = start < 0 ? i : start;
            found++;
        }
    if (found > 1) {
        snprintf(err, SCENE_ERR_LEN, "'%s': %s has %d [%s] sections; a key of a repeated section cannot be set",
                 assign, in, found, section);
        free(text);
        return false;
    }
    if (start < 0) { /* a new section at the end, after a blank line */
        char *blank = dup_string(""), *head = malloc(strlen(section) + 3);
        bool ok = blank && head;
        if (ok) sprintf(head, "[%s]", section);
        ok = ok && push_line(f, f->n, blank, -(1 + index));
        if (!ok) free(blank);
        ok = ok && push_line(f, f->n, head, -(1 + index));
        if (!ok) free(head);
        if (!ok || !push_line(f, f->n, text, -(1 + index))) {
            snprintf(err, SCENE_ERR_LEN, "out of memory");
            if (ok) free(text);
            return false;
        }
        return true;
    }
    int end = start + 1, at = -1, last = start;
    for (; end < f->n && !header_of(f->lines[end].text, name, sizeof name); end++) {
        if (sets_key(f->lines[end].text, key)) {
            if (at >= 0) {
                snprintf(err, SCENE_ERR_LEN, "'%s': %s:%d and %d both set %s.%s", assign, in, f->lines[at].origin,
                         f->lines[end].origin, section, key);
                free(text);
                return false;
            }
            at = end;
        }
        if (!is_blank_or_comment(f->lines[end].text)) last = end;
    }
    if (at >= 0) { /* the line replaced, with its comment (it spoke of the old value) */
        free(f->lines[at].text);
        f->lines[at] = (edit_line){text, -(1 + index)};
        return true;
    }
    if (!push_line(f, last + 1, text, -(1 + index))) {
        snprintf(err, SCENE_ERR_LEN, "out of memory");
        free(text);
        return false;
    }
    return true;
}

/* The parser's "path:line: message" said of the edited file, told of where the line came
   from: the input's line, or the assignment that wrote it. */
static void blame(const edit_file *f, const char *in, const char *tmp, int n_assign, const char *const *assign,
                  const char *msg, char *err)
{
    size_t tl = strlen(tmp);
    int line = 0, used = 0;
    if (!strncmp(msg, tmp, tl) && sscanf(msg + tl, ":%d:%n", &line, &used) == 1 && used > 0 && line >= 1 && line <= f->n) {
        const char *rest = skip_space(msg + tl + used);
        int o = f->lines[line - 1].origin;
        if (o > 0) snprintf(err, SCENE_ERR_LEN, "%s:%d: %s", in, o, rest);
        else if (-o - 1 < n_assign) snprintf(err, SCENE_ERR_LEN, "'%s': %s", assign[-o - 1], rest);
        else snprintf(err, SCENE_ERR_LEN, "%s: %s", in, rest);
    } else if (!strncmp(msg, tmp, tl)) {
        snprintf(err, SCENE_ERR_LEN, "%s%s", in, msg + tl);
    } else {
        snprintf(err, SCENE_ERR_LEN, "%s", msg);
    }
}

bool scene_edit(const char *in, const char *out, int n_assign, const char *const *assign, char *err)
{
    edit_file f = {0};
    char tmp[1100];
    bool ok;
    err[0] = 0;
    if (snprintf(tmp, sizeof tmp, "%s.tmp", out) >= (int)sizeof tmp) {
        snprintf(err, SCENE_ERR_LEN, "%s: the output path is too long", out);
        return false;
    }
    ok = read_file(in, &f, err);
    for (int i = 0; ok && i < n_assign; i++) ok = apply(&f, in, i, assign[i], err);
    if (ok) {
        FILE *fp = fopen(tmp, "w");
        ok = fp != NULL;
        for (int i = 0; ok && i < f.n; i++) ok = fprintf(fp, "%s\n", f.lines[i].text) >= 0;
        if (fp && fclose(fp)) ok = false;
        if (!ok) snprintf(err, SCENE_ERR_LEN, "%s: cannot write (%s)", tmp, strerror(errno));
    }
    if (ok) { /* the result must be a scene: the parser's rules, its messages */
        scene sc;
        char msg[SCENE_ERR_LEN];
        if (scene_load(&sc, tmp, msg)) {
            scene_free(&sc);
            if (rename(tmp, out)) {
                snprintf(err, SCENE_ERR_LEN, "%s: cannot write (%s)", out, strerror(errno));
                ok = false;
            }
        } else {
            blame(&f, in, tmp, n_assign, assign, msg, err);
            ok = false;
        }
    }
    if (!ok) remove(tmp);
    free_file(&f);
    return ok;
}
