/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The instances that make the geometry a part an AP214 reader transfers:
 * a PRODUCT with its definition, whose shape is a
 * GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION of one GEOMETRIC_SET
 * (surfaces, curves, curves on surfaces), in a 3D context that states the
 * length unit, radians, steradians and the distance uncertainty; and the
 * 2D parametric context of the pcurves.
 *
 * The length unit is an SI_UNIT (metre with a prefix) where the model's
 * unit is one, else a CONVERSION_BASED_UNIT (inch, foot, ... or any other
 * size) whose measure is given in metres, so that a reader's product of
 * measure and metre is the size given, exactly.
 */
#include <math.h>

#include "io/step_write.h"

/* Units are matched to this relative difference (as the IGES writer). */
#define PC_STEP_UNIT_MATCH 1e-9

static const struct {
    const char *prefix; /* an SI prefix, or "$" for none */
    double size;
} k_si[] = {{"$", 1.0},         {".MILLI.", 1e-3}, {".CENTI.", 1e-2}, {".DECI.", 1e-1},
            {".KILO.", 1e3},    {".MICRO.", 1e-6}, {".NANO.", 1e-9}};

static const struct {
    const char *name;
    double size;
} k_named[] = {{"INCH", 0.0254},  {"FOOT", 0.3048},  {"MILE", 1609.344},
               {"MIL", 0.0254e-3}, {"MICROINCH", 0.0254e-6}, {"YARD", 0.9144}};

static int near(double a, double b)
{
    return fabs(a - b) <= PC_STEP_UNIT_MATCH * b;
}

/* The length unit as #id (and, for a conversion-based unit, the
 * instances it needs: #id + 1 to #id + 3). */
static void length_unit(pc_text_buf *b, double size, long id)
{
    for (size_t i = 0; i < sizeof k_si / sizeof *k_si; ++i)
        if (near(size, k_si[i].size)) {
            pc_text_buf_printf(b, "#%ld=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(%s,.METRE.));\n", id,
                               k_si[i].prefix);
            return;
        }
    const char *name = "LENGTH UNIT";
    for (size_t i = 0; i < sizeof k_named / sizeof *k_named; ++i)
        if (near(size, k_named[i].size))
            name = k_named[i].name;
    pc_text_buf_printf(b,
                       "#%ld=(CONVERSION_BASED_UNIT('%s',#%ld) LENGTH_UNIT() NAMED_UNIT(#%ld));\n",
                       id, name, id + 1, id + 3);
    pc_text_buf_printf(b, "#%ld=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(", id + 1);
    pc_text_buf_real(b, size);
    pc_text_buf_printf(b, "),#%ld);\n", id + 2);
    pc_text_buf_printf(b, "#%ld=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.));\n", id + 2);
    pc_text_buf_printf(b, "#%ld=DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n", id + 3);
}

static void geometric_set(pc_text_buf *b, const pc_step_out *out, long id)
{
    pc_text_buf_printf(b, "#%ld=GEOMETRIC_SET('',(", id);
    for (size_t i = 0; i < out->set.count; ++i) {
        if (i > 0)
            pc_text_buf_puts(b, i % 8 == 0 ? ",\n" : ",");
        pc_text_buf_printf(b, "#%ld", out->set.items[i]);
    }
    pc_text_buf_puts(b, "));\n");
}

void pc_step_format_context(pc_text_buf *b, const pc_step_out *out, long first)
{
    if (out->has_pcurves)
        pc_text_buf_printf(b,
                           "#%ld=(GEOMETRIC_REPRESENTATION_CONTEXT(2) "
                           "PARAMETRIC_REPRESENTATION_CONTEXT() "
                           "REPRESENTATION_CONTEXT('2D SPACE',''));\n",
                           PC_STEP_PARAMETRIC_CONTEXT_ID);
    const long app = first, product = first + 3, formation = first + 4, definition = first + 6;
    const long shape = first + 7, rep = first + 9, set = first + 10, context = first + 11;
    const long uncertainty = first + 12, angle = first + 13, solid = first + 14;
    const long length = first + 15;
    pc_text_buf_printf(b, "#%ld=APPLICATION_CONTEXT('automotive design');\n", app);
    pc_text_buf_printf(b,
                       "#%ld=APPLICATION_PROTOCOL_DEFINITION('international standard',"
                       "'automotive_design',2000,#%ld);\n",
                       first + 1, app);
    pc_text_buf_printf(b, "#%ld=PRODUCT_CONTEXT('',#%ld,'mechanical');\n", first + 2, app);
    pc_text_buf_printf(b, "#%ld=PRODUCT('libprojcurve','libprojcurve result','',(#%ld));\n",
                       product, first + 2);
    pc_text_buf_printf(b, "#%ld=PRODUCT_DEFINITION_FORMATION('','',#%ld);\n", formation,
                       product);
    pc_text_buf_printf(b, "#%ld=PRODUCT_DEFINITION_CONTEXT('part definition',#%ld,'design');\n",
                       first + 5, app);
    pc_text_buf_printf(b, "#%ld=PRODUCT_DEFINITION('design','',#%ld,#%ld);\n", definition,
                       formation, first + 5);
    pc_text_buf_printf(b, "#%ld=PRODUCT_DEFINITION_SHAPE('','',#%ld);\n", shape, definition);
    pc_text_buf_printf(b, "#%ld=SHAPE_DEFINITION_REPRESENTATION(#%ld,#%ld);\n", first + 8, shape,
                       rep);
    pc_text_buf_printf(b,
                       "#%ld=GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION('',(#%ld),#%ld);\n",
                       rep, set, context);
    geometric_set(b, out, set);
    pc_text_buf_printf(b,
                       "#%ld=(GEOMETRIC_REPRESENTATION_CONTEXT(3) "
                       "GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#%ld)) "
                       "GLOBAL_UNIT_ASSIGNED_CONTEXT((#%ld,#%ld,#%ld)) "
                       "REPRESENTATION_CONTEXT('3D',''));\n",
                       context, uncertainty, length, angle, solid);
    pc_text_buf_printf(b, "#%ld=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(", uncertainty);
    pc_text_buf_real(b, out->uncertainty);
    pc_text_buf_printf(b, "),#%ld,'distance_accuracy_value','');\n", length);
    pc_text_buf_printf(b, "#%ld=(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.));\n",
                       angle);
    pc_text_buf_printf(b, "#%ld=(NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT());\n",
                       solid);
    length_unit(b, out->metres_per_unit, length);
}
