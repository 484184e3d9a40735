// VTK's triangle subdivision filters (vtkLoopSubdivisionFilter, vtkButterflySubdivisionFilter,
// vtkLinearSubdivisionFilter): the one translation unit that includes VTK.
#include <vtkButterflySubdivisionFilter.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkIdList.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkVersion.h>

#include <string>

#include "crossdiv/adapters/vtk.h"

namespace crossdiv::adapters::vtk {
namespace {

/// The mesh as vtkPolyData: double-precision points in our order, one triangle cell per face.
vtkSmartPointer<vtkPolyData> to_vtk(const TriMesh& mesh) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(mesh.num_vertices());
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const Vec3& p = mesh.positions[static_cast<size_t>(v)];
        points->SetPoint(v, p.x(), p.y(), p.z());
    }
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(mesh.num_faces(), 3 * mesh.num_faces());
    for (const Triangle& t : mesh.triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        triangles->InsertNextCell(3, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(triangles);
    return data;
}

/// The polygons of `data` as a PolyMesh (points in VTK's order, cells in its order).
PolyMesh from_vtk(vtkPolyData* data) {
    PolyMesh out;
    const vtkIdType n = data->GetNumberOfPoints();
    out.positions.reserve(static_cast<size_t>(n));
    for (vtkIdType v = 0; v < n; ++v) {
        double p[3];
        data->GetPoint(v, p);
        out.positions.emplace_back(p[0], p[1], p[2]);
    }
    vtkCellArray* polys = data->GetPolys();
    vtkNew<vtkIdList> cell;
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
        polys->GetCellAtId(c, cell);
        for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k) {
            const vtkIdType id = cell->GetId(k);
            if (id < 0 || id >= n)
                throw InvalidResult(std::string("VTK's cell ") + std::to_string(c) + " names point " + std::to_string(id) + " of " +
                                    std::to_string(n));
            out.face_vertices.push_back(static_cast<int>(id));
        }
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
    }
    return out;
}

vtkSmartPointer<vtkSubdivisionFilter> make_filter(Filter filter) {
    switch (filter) {
        case Filter::Loop: return vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
        case Filter::Butterfly: return vtkSmartPointer<vtkButterflySubdivisionFilter>::New();
        case Filter::Linear: break;
    }
    return vtkSmartPointer<vtkLinearSubdivisionFilter>::New();
}

/// VTK reports a refusal through its error macro (an ErrorEvent, else a line on its output
/// window) and returns an empty output: the observer keeps the first message instead, and none
/// reaches the output window.
void keep_first_error(vtkObject*, unsigned long, void* client, void* call) {
    auto& said = *static_cast<std::string*>(client);
    if (said.empty() && call) said = static_cast<const char*>(call);
}

/// `steps` subdivisions of `input` by one call of `filter`.
/// @throws Rejected with VTK's words when it reports an error or makes no triangles.
vtkSmartPointer<vtkPolyData> run(vtkPolyData* input, Filter filter, int steps) {
    const vtkSmartPointer<vtkSubdivisionFilter> f = make_filter(filter);
    std::string said;
    vtkNew<vtkCallbackCommand> observer;
    observer->SetCallback(keep_first_error);
    observer->SetClientData(&said);
    f->AddObserver(vtkCommand::ErrorEvent, observer);
    f->AddObserver(vtkCommand::WarningEvent, observer);
    // The pipeline then reports that the filter failed, which says nothing more.
    f->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
    f->SetNumberOfSubdivisions(steps);
    f->SetInputData(input);
    f->Update();
    vtkPolyData* out = f->GetOutput();
    if (!said.empty()) throw Rejected(std::string(filter_name(filter)) + ": " + said);
    if (input->GetNumberOfPolys() > 0 && out->GetNumberOfPolys() == 0)
        throw Rejected(std::string(filter_name(filter)) + " returned no triangles");
    auto kept = vtkSmartPointer<vtkPolyData>::New();
    kept->ShallowCopy(out);
    return kept;
}

}  // namespace

const char* filter_name(Filter filter) {
    switch (filter) {
        case Filter::Loop: return "vtkLoopSubdivisionFilter";
        case Filter::Butterfly: return "vtkButterflySubdivisionFilter";
        case Filter::Linear: break;
    }
    return "vtkLinearSubdivisionFilter";
}

LevelTrace subdivide(const TriMesh& mesh, Filter filter, int levels) {
    vtkSmartPointer<vtkPolyData> current = to_vtk(mesh);
    LevelTrace trace{from_vtk(current)};
    for (int l = 1; l <= levels; ++l) {
        current = run(current, filter, 1);
        trace.push_back(from_vtk(current));
    }
    return trace;
}

size_t subdivide_native(const TriMesh& mesh, Filter filter, int levels) {
    return static_cast<size_t>(run(to_vtk(mesh), filter, levels)->GetNumberOfPolys());
}

std::string version() { return std::string("VTK ") + vtkVersion::GetVTKVersion(); }

}  // namespace crossdiv::adapters::vtk
