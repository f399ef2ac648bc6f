/* SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <string.h>

#include "io/io_model.h"

#define PC_IGES_LETTER_COLUMN 72
/* Columns a first record may be off by and still be recognised. */
#define PC_IGES_SHIFT_TOLERANCE 8
/* Of the 7-column sequence number, at least this many columns must
 * follow the letter (fewer when the record is shifted right). */
#define PC_IGES_MIN_SEQUENCE_DIGITS 4

static size_t skip_space_and_bom(const char *data, size_t len)
{
    size_t pos = 0;
    if (len >= 3 && (unsigned char)data[0] == 0xEF && (unsigned char)data[1] == 0xBB &&
        (unsigned char)data[2] == 0xBF)
        pos = 3;
    while (pos < len && isspace((unsigned char)data[pos]))
        ++pos;
    return pos;
}

/* IGES: the first record ends with a section letter (S, or G without a
 * start section) and a sequence number. The letter belongs in column 73;
 * a record whose columns are shifted is still taken as IGES here so that
 * the reader can say which line is wrong. */
static int looks_like_iges(const char *data, size_t len)
{
    const char *nl = memchr(data, '\n', len);
    size_t first = nl ? (size_t)(nl - data) : len;
    if (first > 0 && data[first - 1] == '\r')
        --first;
    if (!nl && len > 80)
        first = 80; /* bare records */
    if (first <= PC_IGES_LETTER_COLUMN - PC_IGES_SHIFT_TOLERANCE ||
        first > 80 + PC_IGES_SHIFT_TOLERANCE)
        return 0;
    size_t at = first;
    while (at > 0 && (isdigit((unsigned char)data[at - 1]) || data[at - 1] == ' '))
        --at;
    if (at == 0 || first - at < PC_IGES_MIN_SEQUENCE_DIGITS)
        return 0;
    const char c = data[at - 1];
    return c == 'S' || c == 'G' || c == 'C' || c == 'B';
}

/* Newell teapot text: a first line holding a single count. */
static int looks_like_teapot(const char *data, size_t len, size_t pos)
{
    size_t digits = 0;
    while (pos < len && isdigit((unsigned char)data[pos])) {
        ++pos;
        ++digits;
    }
    while (pos < len && (data[pos] == ' ' || data[pos] == '\t' || data[pos] == '\r'))
        ++pos;
    return digits > 0 && pos < len && data[pos] == '\n';
}

pc_file_format pc_detect_format(const char *data, size_t len)
{
    if (looks_like_iges(data, len))
        return PC_FORMAT_IGES;
    const size_t pos = skip_space_and_bom(data, len);
    static const char step_magic[] = "ISO-10303-21";
    if (len - pos >= sizeof step_magic - 1 &&
        memcmp(data + pos, step_magic, sizeof step_magic - 1) == 0)
        return PC_FORMAT_STEP;
    if (pos < len && data[pos] == '<')
        return PC_FORMAT_GISMO;
    if (looks_like_teapot(data, len, pos))
        return PC_FORMAT_TEAPOT;
    return PC_FORMAT_UNKNOWN;
}
