// SPDX-License-Identifier: BSD-3-Clause
// Open CASCADE's BRepProj_Projection onto a whole model (occt_shape.h).
#include "occt_shape.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepProj_Projection.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "occt_read.h"

extern "C" {
#include "timing.h"
}

struct pcb_occt_model {
    TopoDS_Shape shape;
};

namespace {

/* The curve as OCCT's B-spline: distinct knots with multiplicities. */
Handle(Geom_BSplineCurve) make_curve(const pcb_nurbs_data &d)
{
    std::vector<double> k;
    std::vector<int> m;
    const size_t n_knots = d.n_u + static_cast<size_t>(d.deg_u) + 1;
    for (size_t i = 0; i < n_knots; ++i) {
        if (!k.empty() && d.knots_u[i] == k.back()) {
            ++m.back();
        } else {
            k.push_back(d.knots_u[i]);
            m.push_back(1);
        }
    }
    const int n = static_cast<int>(d.n_u);
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) {
        const size_t s = static_cast<size_t>(i);
        poles.SetValue(i + 1, gp_Pnt(d.ctrl[3 * s], d.ctrl[3 * s + 1], d.ctrl[3 * s + 2]));
        weights.SetValue(i + 1, d.weights[s]);
    }
    TColStd_Array1OfReal ak(1, static_cast<int>(k.size()));
    TColStd_Array1OfInteger am(1, static_cast<int>(m.size()));
    for (size_t i = 0; i < k.size(); ++i) {
        ak.SetValue(static_cast<int>(i) + 1, k[i]);
        am.SetValue(static_cast<int>(i) + 1, m[i]);
    }
    if (d.rational)
        return new Geom_BSplineCurve(poles, weights, ak, am, d.deg_u);
    return new Geom_BSplineCurve(poles, ak, am, d.deg_u);
}

TopoDS_Shape project_once(const TopoDS_Wire &wire, const TopoDS_Shape &shape, int conical,
                          const double v[3], bool &found)
{
    if (conical) {
        BRepProj_Projection p(wire, shape, gp_Pnt(v[0], v[1], v[2]));
        found = p.IsDone();
        return found ? p.Shape() : TopoDS_Shape();
    }
    BRepProj_Projection p(wire, shape, gp_Dir(v[0], v[1], v[2]));
    found = p.IsDone();
    return found ? p.Shape() : TopoDS_Shape();
}

/* Counts and samples of the result's wires and edges. */
void describe(const TopoDS_Shape &res, size_t per_edge, pcb_occt_shape_out *out,
              std::vector<double> &pts)
{
    out->wires = out->edges = 0;
    out->poles = 0;
    if (res.IsNull())
        return;
    for (TopExp_Explorer w(res, TopAbs_WIRE); w.More(); w.Next())
        ++out->wires;
    for (TopExp_Explorer e(res, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge &edge = TopoDS::Edge(e.Current());
        ++out->edges;
        double a = 0, b = 0;
        Handle(Geom_Curve) c = BRep_Tool::Curve(edge, a, b);
        Handle(Geom_BSplineCurve) bs = Handle(Geom_BSplineCurve)::DownCast(c);
        if (!bs.IsNull())
            out->poles += bs->NbPoles();
        BRepAdaptor_Curve ad(edge);
        const double t0 = ad.FirstParameter(), t1 = ad.LastParameter();
        for (size_t i = 0; i < per_edge; ++i) {
            const gp_Pnt q = ad.Value(t0 + (t1 - t0) * static_cast<double>(i) /
                                               static_cast<double>(per_edge - 1));
            pts.push_back(q.X());
            pts.push_back(q.Y());
            pts.push_back(q.Z());
        }
    }
}

} // namespace

extern "C" pcb_occt_model *pcb_occt_model_read(const char *path)
{
    pcb_occt_model *m = new pcb_occt_model;
    double s = 0.0;
    if (pcb_occt_read_shape(path, &s, &m->shape) != 0) {
        delete m;
        return nullptr;
    }
    return m;
}

extern "C" void pcb_occt_model_free(pcb_occt_model *m)
{
    delete m;
}

extern "C" int pcb_occt_shape_project(const pcb_occt_model *m, const pcb_nurbs_data *curve,
                                      int conical, const double vec[3], int reps,
                                      size_t samples_per_edge, pcb_occt_shape_out *out)
{
    out->samples = nullptr;
    out->n_samples = 0;
    out->note[0] = '\0';
    out->ms = -1.0;
    if (reps > PCB_MAX_REPS)
        reps = PCB_MAX_REPS;
    if (reps < 1)
        reps = 1;
    if (samples_per_edge < 2)
        samples_per_edge = 2;
    try {
        const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(make_curve(*curve));
        const TopoDS_Wire wire = BRepBuilderAPI_MakeWire(edge);
        double t[PCB_MAX_REPS];
        TopoDS_Shape res;
        for (int i = 0; i <= reps; ++i) {
            bool found = false;
            const double t0 = pcb_now_s();
            res = project_once(wire, m->shape, conical, vec, found);
            const double dt = pcb_now_s() - t0;
            if (!found) {
                /* nothing hit: an empty result, as ours gives */
                res = TopoDS_Shape();
            }
            if (i > 0)
                t[i - 1] = dt;
        }
        out->ms = 1e3 * pcb_median(t, static_cast<size_t>(reps));
        std::vector<double> pts;
        describe(res, samples_per_edge, out, pts);
        out->n_samples = pts.size() / 3;
        out->samples = static_cast<double *>(std::malloc((pts.size() + 1) * sizeof(double)));
        if (out->samples == nullptr) {
            std::snprintf(out->note, sizeof out->note, "out of memory");
            return -1;
        }
        for (size_t i = 0; i < pts.size(); ++i)
            out->samples[i] = pts[i];
    } catch (const Standard_Failure &e) {
        std::snprintf(out->note, sizeof out->note, "Open CASCADE: %s",
                      e.GetMessageString() ? e.GetMessageString() : "exception");
        return -1;
    }
    return 0;
}

extern "C" void pcb_occt_shape_out_free(pcb_occt_shape_out *out)
{
    std::free(out->samples);
    out->samples = nullptr;
    out->n_samples = 0;
}
