// SPDX-License-Identifier: BSD-3-Clause
// Open CASCADE's STEP and IGES readers, timed for the brep bench.
#include "occt_read.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Shape.hxx>

#include <cstring>

extern "C" {
#include "timing.h"
}

static bool is_step(const char *path)
{
    const char *dot = std::strrchr(path, '.');
    return dot != nullptr && (std::strcmp(dot, ".stp") == 0 || std::strcmp(dot, ".step") == 0);
}

template <typename Reader> static bool read_with(const char *path, TopoDS_Shape &shape)
{
    Reader reader;
    if (reader.ReadFile(path) != IFSelect_RetDone)
        return false;
    reader.TransferRoots();
    shape = reader.OneShape();
    return true;
}

int pcb_occt_read_shape(const char *path, double *seconds, TopoDS_Shape *shape)
{
    // the readers' progress messages would interleave with the table
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    const double t0 = pcb_now_s();
    const bool ok = is_step(path) ? read_with<STEPControl_Reader>(path, *shape)
                                  : read_with<IGESControl_Reader>(path, *shape);
    *seconds = pcb_now_s() - t0;
    return ok ? 0 : -1;
}

extern "C" int pcb_occt_read(const char *path, double *seconds, int *faces, int *wires)
{
    TopoDS_Shape shape;
    if (pcb_occt_read_shape(path, seconds, &shape) != 0)
        return -1;
    *faces = *wires = 0;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
        ++*faces;
    for (TopExp_Explorer e(shape, TopAbs_WIRE); e.More(); e.Next())
        ++*wires;
    return 0;
}
