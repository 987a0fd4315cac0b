#include <ivis/core/raw_mesh_import.h>

#include <ivis/core/errors.h>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/IO/reader/OFFReader.hh>
#include <OpenMesh/Core/Mesh/BaseKernel.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <array>
#include <cctype>
#include <map>
#include <mutex>
#include <sstream>

namespace ivis::core::detail {
namespace {

namespace omio = OpenMesh::IO;

/// Property storage without connectivity: the PLY reader adds custom per-vertex and per-face
/// properties to the importer's kernel by name (Options::Custom), one slot per element.
class PropertyKernel final : public OpenMesh::BaseKernel {
public:
    OpenMesh::VertexHandle addVertex()
    {
        vprops_resize(++mVertices);
        return OpenMesh::VertexHandle(int(mVertices - 1));
    }
    OpenMesh::FaceHandle addFace()
    {
        fprops_resize(++mFaces);
        return OpenMesh::FaceHandle(int(mFaces - 1));
    }
    size_t n_vertices() const override { return mVertices; }
    size_t n_faces() const override { return mFaces; }

private:
    std::size_t mVertices = 0;
    std::size_t mFaces = 0;
};

/// Importer that records positions and faces as raw index lists: no half-edge topology, so
/// OpenMesh never refuses a non-manifold face, and out-of-range indices reach us instead of being
/// dropped. If a token could not be parsed, OpenMesh's readers carry on with stale values; the
/// importer reports the failed stream at the next vertex or face instead.
class RawImporter final : public omio::BaseImporter {
public:
    RawImporter(const std::istream& stream, std::string path, bool oneBased)
        : mStream(stream), mPath(std::move(path)), mOneBased(oneBased)
    {
    }

    /// What was read, with every numeric vertex property as a point array and every numeric face
    /// property as a cell array, in the order the file declares them.
    RawMesh take()
    {
        for (auto it = mProperties.vprops_begin(); it != mProperties.vprops_end(); ++it) {
            if (*it != nullptr) addArray<OpenMesh::VPropHandleT>((*it)->name(), Association::Point);
        }
        for (auto it = mProperties.fprops_begin(); it != mProperties.fprops_end(); ++it) {
            if (*it != nullptr) addArray<OpenMesh::FPropHandleT>((*it)->name(), Association::Cell);
        }
        mMesh.cellCount = mMesh.faceCount();
        return std::move(mMesh);
    }

    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override
    {
        checkStream("vertex", mMesh.positions.size());
        mMesh.positions.emplace_back(p[0], p[1], p[2]);
        return mProperties.addVertex();
    }
    OpenMesh::VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3f(0.0f)); }
    void set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) override
    {
        checkStream("vertex", std::size_t(v.idx()));
        IVIS_CHECK(v.idx() >= 0 && std::size_t(v.idx()) < mMesh.positions.size());
        mMesh.positions[std::size_t(v.idx())] = glm::dvec3(p[0], p[1], p[2]);
    }
    OpenMesh::FaceHandle add_face(const VHandles& corners) override
    {
        checkStream("face", mMesh.faceEnds.size());
        for (const OpenMesh::VertexHandle v : corners) mMesh.corners.push_back(v.idx());
        mMesh.faceEnds.push_back(mMesh.corners.size());
        return mProperties.addFace();  // a real handle, so PLY face properties have a slot
    }
    OpenMesh::BaseKernel* kernel() override { return &mProperties; }
    size_t n_vertices() const override { return mMesh.positions.size(); }
    size_t n_faces() const override { return mMesh.faceEnds.size(); }
    size_t n_edges() const override { return 0; }

    // Everything below is data we do not keep (normals, colours, texture coordinates, status)
    // or half-edge connectivity, which only the OM format writes directly.
    OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override
    {
        return OpenMesh::HalfedgeHandle();
    }
    OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }
    void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                            const std::vector<OpenMesh::Vec2f>&) override {}
    void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                            const std::vector<OpenMesh::Vec3f>&) override {}
    void set_face_texindex(OpenMesh::FaceHandle, int) override {}
    void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
    void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
    void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
    void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
    void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
    void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
    void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
    void request_face_texcoords2D() override {}
    void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
    void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
    void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
    void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
    void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
    void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void add_texture_information(int, std::string) override {}

private:
    /// Adds property @a name as an array when its C++ type (as OpenMesh's PLY reader declares it
    /// for the file's type) is numeric; list properties and others are left out.
    template <template <typename> class Handle>
    void addArray(const std::string& name, Association association)
    {
        DataArray array{name, association, ValueType::Float32, 1, {}};
        const bool found = collect<Handle, float>(array, ValueType::Float32) ||
                           collect<Handle, double>(array, ValueType::Float64) ||
                           collect<Handle, signed char>(array, ValueType::Int8) ||
                           collect<Handle, unsigned char>(array, ValueType::UInt8) ||
                           collect<Handle, short>(array, ValueType::Int16) ||
                           collect<Handle, unsigned short>(array, ValueType::UInt16) ||
                           collect<Handle, int>(array, ValueType::Int32) ||
                           collect<Handle, unsigned int>(array, ValueType::UInt32);
        if (found) mMesh.arrays.push_back(std::move(array));
    }
    /// Copies the property named array.name when it holds values of type @a T.
    template <template <typename> class Handle, typename T>
    bool collect(DataArray& array, ValueType type)
    {
        Handle<T> handle;
        if (!mProperties.get_property_handle(handle, array.name)) return false;
        array.type = type;
        for (const T v : mProperties.property(handle).data_vector()) array.values.push_back(double(v));
        return true;
    }

    void checkStream(const char* element, std::size_t index) const
    {
        if (!mStream.fail()) return;
        failInput(mPath, "cannot read " + std::string(element) + " " + std::to_string(index + mOneBased) +
                             " (a value is missing, not a number or out of range)");
    }

    const std::istream& mStream;
    std::string mPath;
    bool mOneBased;
    RawMesh mMesh;
    PropertyKernel mProperties;
};

/// Silences OpenMesh's log streams while alive and restores their previous state.
class QuietOpenMesh {
public:
    QuietOpenMesh()
    {
        for (std::size_t i = 0; i < kStreams.size(); ++i) {
            mWasEnabled[i] = kStreams[i]().is_enabled();
            kStreams[i]().disable();
        }
    }
    ~QuietOpenMesh()
    {
        for (std::size_t i = 0; i < kStreams.size(); ++i) {
            if (mWasEnabled[i]) kStreams[i]().enable();
        }
    }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

private:
    static constexpr std::array<OpenMesh::mostream& (*)(), 3> kStreams{&omerr, &omlog, &omout};
    std::array<bool, 3> mWasEnabled{};
};

/// OpenMesh's reader singletons and log streams are process-wide state.
std::mutex gOpenMeshMutex;

/// The mesh of an ASCII STL's facet @a corners (three a facet): corners with equal coordinates
/// merged into one vertex, numbered by first appearance, and facets with a repeated vertex dropped,
/// as OpenMesh's STL reader does, but compared in double, where OpenMesh compares single-precision
/// values and merges the distinct corners of a mesh far from its origin.
RawMesh meshOfStlCorners(const std::vector<glm::dvec3>& corners)
{
    RawMesh raw;
    std::map<std::array<double, 3>, std::int64_t> vertexAt;
    std::array<std::int64_t, 3> facet{};
    for (std::size_t c = 0; c < corners.size(); ++c) {
        // + 0.0 makes -0 and 0 one key.
        const std::array<double, 3> key{corners[c].x + 0.0, corners[c].y + 0.0, corners[c].z + 0.0};
        const auto [at, added] = vertexAt.emplace(key, std::int64_t(raw.positions.size()));
        if (added) raw.positions.push_back(corners[c]);
        facet[c % 3] = at->second;
        if (c % 3 != 2 || facet[0] == facet[1] || facet[1] == facet[2] || facet[0] == facet[2]) continue;
        raw.corners.insert(raw.corners.end(), facet.begin(), facet.end());
        raw.faceEnds.push_back(raw.corners.size());
    }
    raw.cellCount = raw.faceCount();
    return raw;
}

/// "not a valid PLY mesh" style name.
std::string formatLabel(MeshFormat format)
{
    std::string label = formatName(format);
    for (char& c : label) c = char(std::toupper(static_cast<unsigned char>(c)));
    return label;
}

}  // namespace

RawMesh readOpenMeshFile(const std::string& path, MeshFormat format, std::string data)
{
    MeshLayout layout = checkMeshLayout(path, format, data);
    if (format == MeshFormat::Stl && !layout.binaryStl) {
        RawMesh raw = meshOfStlCorners(layout.stlCorners);
        raw.skippedFaces = layout.facesInFile - raw.faceCount();
        return raw;
    }
    // OpenMesh parses exactly the bytes that were checked.
    std::istringstream stream(data);
    std::string().swap(data);
    RawImporter importer(stream, path, format == MeshFormat::Obj);
    omio::Options options = omio::Options::Custom;
    if (layout.binaryStl) options += omio::Options::Binary;
    bool ok = false;
    {
        std::lock_guard<std::mutex> lock(gOpenMeshMutex);
        QuietOpenMesh quiet;
        // The OFF stream reader takes its binary/normal/colour flags from the last header check.
        ok = (format != MeshFormat::Off || omio::OFFReader().can_u_read(path)) &&
             omio::IOManager().read(stream, formatName(format), importer, options);
    }
    if (!ok) failInput(path, "not a valid " + formatLabel(format) + " mesh");
    RawMesh raw = importer.take();
    // OpenMesh hands over single-precision points: the file's own, in double, replace them.
    if (layout.filePoints.size() == raw.positions.size()) raw.positions = std::move(layout.filePoints);
    for (const MeshLayout::BytePlyProperty& p : layout.asciiPlyBytes)
        for (DataArray& array : raw.arrays)
            if (array.name == p.name && array.association == p.association) array.type = p.type;
    // Faces OpenMesh skipped itself (OBJ/STL faces with repeated corners) count as degenerate.
    raw.skippedFaces = layout.facesInFile > raw.faceCount() ? layout.facesInFile - raw.faceCount() : 0;
    return raw;
}

}  // namespace ivis::core::detail
