/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The length unit of a STEP file, from its representation context: a
 * conversion-based unit ('INCH', 'FOOT') or an SI unit of metres with its
 * prefix (SI_UNIT(.MILLI.,.METRE.)). Read from the text, as the geometry
 * reader needs no unit itself.
 */
#include <string.h>

#include "io/io_model.h"

/* Unit names a conversion-based length unit can carry, and the unit. */
static const struct {
    const char *name;
    int unit;
} conversion_units[] = {{"'INCH'", PROJCURVE_UNIT_INCH}, {"'FOOT'", PROJCURVE_UNIT_FOOT},
                        {"'MIL'", PROJCURVE_UNIT_MIL}, {"'MILE'", PROJCURVE_UNIT_MILE}};

/* SI prefixes of METRE and the unit. */
static const struct {
    const char *prefix;
    int unit;
} si_prefixes[] = {{".MILLI.", PROJCURVE_UNIT_MM},  {".CENTI.", PROJCURVE_UNIT_CM},
                   {".KILO.", PROJCURVE_UNIT_KM},   {".MICRO.", PROJCURVE_UNIT_MICRON},
                   {"$", PROJCURVE_UNIT_METRE}};

/* The first occurrence of needle in text[0..len). */
static const char *find(const char *text, size_t len, const char *needle)
{
    const size_t n = strlen(needle);
    for (size_t i = 0; i + n <= len; ++i)
        if (text[i] == needle[0] && memcmp(text + i, needle, n) == 0)
            return text + i;
    return NULL;
}

static const char *skip_blanks(const char *p, const char *end)
{
    while (p < end && (*p == ' ' || *p == '\r' || *p == '\n' || *p == '\t'))
        ++p;
    return p;
}

int pc_step_length_unit(const char *text, size_t len)
{
    const char *end = text + len;
    for (const char *p = find(text, len, "CONVERSION_BASED_UNIT"); p != NULL;
         p = find(p + 1, (size_t)(end - p - 1), "CONVERSION_BASED_UNIT")) {
        const char *q = skip_blanks(p + strlen("CONVERSION_BASED_UNIT"), end);
        if (q < end && *q == '(')
            q = skip_blanks(q + 1, end);
        for (size_t k = 0; k < sizeof conversion_units / sizeof *conversion_units; ++k) {
            const size_t n = strlen(conversion_units[k].name);
            if ((size_t)(end - q) >= n && memcmp(q, conversion_units[k].name, n) == 0)
                return conversion_units[k].unit;
        }
    }
    for (const char *p = find(text, len, "SI_UNIT("); p != NULL;
         p = find(p + 1, (size_t)(end - p - 1), "SI_UNIT(")) {
        const char *q = skip_blanks(p + strlen("SI_UNIT("), end);
        for (size_t k = 0; k < sizeof si_prefixes / sizeof *si_prefixes; ++k) {
            const size_t n = strlen(si_prefixes[k].prefix);
            if ((size_t)(end - q) < n || memcmp(q, si_prefixes[k].prefix, n) != 0)
                continue;
            const char *r = skip_blanks(q + n, end);
            if (r < end && *r == ',')
                r = skip_blanks(r + 1, end);
            if ((size_t)(end - r) >= 7 && memcmp(r, ".METRE.", 7) == 0)
                return si_prefixes[k].unit;
        }
    }
    return PROJCURVE_UNIT_UNKNOWN;
}
