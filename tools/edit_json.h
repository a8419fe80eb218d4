/* tools/edit_json: the strict reader of `scaf edit`'s request bodies.
 *
 * Every request body of the editor is one flat JSON object whose values
 * are numbers: {"chart": 3, "dx": 0.25, "dy": -0.5, "angle": 0.1}. The
 * reader takes exactly that and nothing else: RFC 8259 number syntax (no
 * NaN, no hex, no leading '+' or zeros), keys the caller lists, each at
 * most once, the required ones present, nothing after the closing brace.
 * Anything else is refused with a message naming the byte offset and
 * what is wrong, and the caller's values are left as they were.
 */
#ifndef SCAF_TOOLS_EDIT_JSON_H
#define SCAF_TOOLS_EDIT_JSON_H

#include <stddef.h>

typedef enum edit_json_kind {
    EDIT_JSON_NUMBER,  /* any finite number */
    EDIT_JSON_INTEGER, /* an integer in [0, 2^31 - 1] */
} edit_json_kind;

typedef struct edit_json_field {
    const char *key;
    edit_json_kind kind;
    int required;
    double value; /* out: the number (when seen) */
    int seen;     /* out: 1 when the key was in the object */
} edit_json_field;

/* Values other than numbers, for the requests that need them (the
 * transform of a selection: {"charts": [3, 5], "op": "rotate", "angle":
 * 0.5, "pivot": [1.5, 2]}): a word (printable ASCII, no escapes, at most
 * 31 characters), an array of integers in [0, 2^31 - 1] or of numbers
 * (at most cap of them, into the caller's list), or true / false. */
typedef enum edit_json_extra_kind {
    EDIT_JSON_WORD,
    EDIT_JSON_INTEGERS,
    EDIT_JSON_NUMBERS,
    EDIT_JSON_BOOL
} edit_json_extra_kind;

typedef struct edit_json_extra {
    const char *key;
    edit_json_extra_kind kind;
    int required;
    double *list; /* in: room for cap values; out: the array's (INTEGERS, NUMBERS) */
    int cap;
    int len;       /* out: values in list */
    char word[32]; /* out: the word (WORD) */
    int flag;      /* out: 1 for true (BOOL) */
    int seen;      /* out */
} edit_json_extra;

/* edit_json_parse with extra keys besides the numeric fields; on 0 nothing
 * of fields or extra is changed. */
int edit_json_parse_extra(const char *body, size_t len, edit_json_field *fields, int n,
                          edit_json_extra *extra, int nextra, char *msg, size_t size);

/* Parse body[0..len) (need not be NUL-terminated) into the n fields.
 * Returns 1, or 0 with msg (size bytes) saying why; on 0 no field's
 * value or seen is changed. */
int edit_json_parse(const char *body, size_t len, edit_json_field *fields, int n, char *msg,
                    size_t size);

#endif
