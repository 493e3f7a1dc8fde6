#include "cad/instances.h"

#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "cad/occt_failure.h"
#include "common/memory_budget.h"

namespace tessera {
namespace {

// The compound's members that are not compounds, located and oriented as the shape places
// them (TopoDS_Iterator composes both), in the depth-first order TopExp::MapShapes walks.
void collectLeaves(const TopoDS_Shape& shape, std::vector<TopoDS_Shape>& leaves) {
  if (shape.ShapeType() != TopAbs_COMPOUND) {
    leaves.push_back(shape);
    return;
  }
  for (TopoDS_Iterator it(shape); it.More(); it.Next()) collectLeaves(it.Value(), leaves);
}

// A motion that keeps distances and sides: no scale, no mirror (a mirrored copy's triangles
// would face inwards; a scaled one would be off its surface by the scale times δ).
bool isRigid(const gp_Trsf& motion) {
  return std::abs(motion.ScaleFactor() - 1.0) <= 1e-12 &&
         motion.HVectorialPart().Determinant() > 0.0;
}

// Leaf TShapes that share a face, edge or vertex with another leaf TShape: a copy of either could
// not weld to the other, so neither is copied.
std::unordered_set<const TopoDS_TShape*> entangledParts(const std::vector<TopoDS_Shape>& leaves) {
  std::unordered_map<const TopoDS_TShape*, const TopoDS_TShape*> ownerOf;
  std::unordered_set<const TopoDS_TShape*> seen, entangled;
  for (const TopoDS_Shape& leaf : leaves) {
    const TopoDS_TShape* part = leaf.TShape().get();
    if (!seen.insert(part).second) continue;
    for (TopAbs_ShapeEnum kind : {TopAbs_FACE, TopAbs_EDGE, TopAbs_VERTEX})
      for (TopExp_Explorer e(leaf, kind); e.More(); e.Next()) {
        const auto [at, added] = ownerOf.emplace(e.Current().TShape().get(), part);
        if (!added && at->second != part) entangled.insert({part, at->second});
      }
  }
  return entangled;
}

// The number of distinct faces and edges of a leaf (its TopExp::MapShapes extents), by part.
struct PartCounts {
  uint32_t faces = 0, edges = 0;
};

PartCounts countsOf(const TopoDS_Shape& leaf) {
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(leaf, TopAbs_FACE, faces);
  TopExp::MapShapes(leaf, TopAbs_EDGE, edges);
  return {uint32_t(faces.Extent()), uint32_t(edges.Extent())};
}

// Adds the faces (or edges) of an entangled leaf that `met` does not hold yet, numbering them
// from `count` on; appends the new numbers to `numbers` (the converted shape meets them there).
void numberShared(const TopoDS_Shape& leaf, TopAbs_ShapeEnum kind, TopTools_IndexedMapOfShape& met,
                  uint32_t& count, std::vector<uint32_t>& numbers) {
  for (TopExp_Explorer e(leaf, kind); e.More(); e.Next()) {
    const int before = met.Extent();
    if (met.Add(e.Current()) > before) numbers.push_back(count++);
  }
}

void appendRange(std::vector<uint32_t>& numbers, uint32_t first, uint32_t count) {
  for (uint32_t k = 0; k < count; ++k) numbers.push_back(first + k);
}

}  // namespace

InstancePlan planInstances(const TopoDS_Shape& shape) {
  InstancePlan plan;
  std::vector<TopoDS_Shape> leaves;
  collectLeaves(shape, leaves);
  // Per leaf: -1 meshed in place, -2 left out (a part again at a place it has already, which
  // the model's maps hold once), else the index of the part's first leaf it copies.
  std::vector<long> role(leaves.size(), -1);
  std::unordered_map<const TopoDS_TShape*, size_t> firstLeaf;
  TopTools_MapOfShape placed;  // by TShape and location, as the model's maps key them
  bool anyCopy = false;
  for (size_t i = 0; i < leaves.size(); ++i) {
    const auto [at, added] = firstLeaf.emplace(leaves[i].TShape().get(), i);
    if (!placed.Add(leaves[i])) {
      role[i] = -2;
      continue;
    }
    if (added) continue;
    const TopoDS_Shape& first = leaves[at->second];
    gp_Trsf motion = leaves[i].Location().Transformation();
    motion.Multiply(first.Location().Transformation().Inverted());
    if (leaves[i].Orientation() == first.Orientation() && isRigid(motion)) {
      role[i] = long(at->second);
      anyCopy = true;
    }
  }
  if (!anyCopy) return plan;
  const std::unordered_set<const TopoDS_TShape*> entangled = entangledParts(leaves);
  for (size_t i = 0; i < leaves.size(); ++i)
    if (role[i] >= 0 && entangled.count(leaves[i].TShape().get())) role[i] = -1;
  if (std::none_of(role.begin(), role.end(), [](long r) { return r >= 0; })) return plan;

  BRep_Builder builder;
  TopoDS_Compound parts;
  builder.MakeCompound(parts);
  for (size_t i = 0; i < leaves.size(); ++i)
    if (role[i] == -1) builder.Add(parts, leaves[i]);
  plan.meshShape = parts;

  // The whole model's numbers, as TopExp::MapShapes gives them, counted leaf by leaf instead of
  // mapped (mapping the model and each copy was 4 of 16 ms on 64 copies): a leaf of a part that
  // shares nothing with another part brings faces and edges not met before (its other places
  // are other locations), in its own MapShapes order; entangled leaves may share, so their
  // shapes go through maps.
  std::unordered_map<const TopoDS_TShape*, PartCounts> counts;
  TopTools_IndexedMapOfShape sharedFaces, sharedEdges;
  std::unordered_map<size_t, size_t> partOfLeaf;  // a part's first leaf → its index in parts
  std::vector<bool> copied(leaves.size(), false);  // leaves that a copy moves
  for (long r : role)
    if (r >= 0) copied[size_t(r)] = true;
  uint32_t faces = 0, edges = 0;
  for (size_t i = 0; i < leaves.size(); ++i) {
    if (role[i] == -2) continue;
    const TopoDS_TShape* tshape = leaves[i].TShape().get();
    if (entangled.count(tshape)) {  // never a copy nor copied
      numberShared(leaves[i], TopAbs_FACE, sharedFaces, faces, plan.numbering.faces);
      numberShared(leaves[i], TopAbs_EDGE, sharedEdges, edges, plan.numbering.edges);
      continue;
    }
    auto [at, added] = counts.emplace(tshape, PartCounts{});
    if (added) at->second = countsOf(leaves[i]);
    const PartCounts c = at->second;
    if (role[i] == -1) {
      appendRange(plan.numbering.faces, faces, c.faces);
      appendRange(plan.numbering.edges, edges, c.edges);
      if (copied[i]) {
        partOfLeaf.emplace(i, plan.parts.size());
        plan.parts.push_back({leaves[i], faces, edges, c.faces, c.edges});
      }
    } else {
      const size_t first = size_t(role[i]);
      InstanceCopy copy;
      copy.part = partOfLeaf.at(first);  // its first place came before
      copy.motion = leaves[i].Location().Transformation();
      copy.motion.Multiply(leaves[first].Location().Transformation().Inverted());
      copy.faceBase = faces;
      copy.edgeBase = edges;
      plan.copies.push_back(std::move(copy));
    }
    faces += c.faces;
    edges += c.edges;
  }
  plan.modelFaces = faces;
  plan.modelEdges = edges;
  return plan;
}

InstancePlan planCadInstances(const CadFile& file) {
  try {
    return planInstances(file.shape);
  } catch (const Standard_Failure& failure) {
    throwAsInputError(failure, file.path, "finding its repeated parts");
  }
}

double plannedModelDiagonal(const InstancePlan& plan, const CadFile& file) {
  if (plan.copies.empty()) return cadModelDiagonal(file);
  return checkedCadDiagonal(file, [&] {
    Bnd_Box box;
    BRepBndLib::Add(plan.meshShape, box);
    std::vector<Bnd_Box> parts(plan.parts.size());
    for (size_t p = 0; p < parts.size(); ++p) BRepBndLib::Add(plan.parts[p].firstLeaf, parts[p]);
    for (const InstanceCopy& copy : plan.copies) box.Add(parts[copy.part].Transformed(copy.motion));
    return box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());  // as defaultCadTolerance
  });
}

namespace {

// Where a face number lies in the parts: (part, slot), for the faces of parts that have copies.
struct PartSlot {
  size_t part = 0, slot = 0;
};

// The parts by their first place's face numbers, for slotOf.
std::vector<std::pair<uint32_t, size_t>> partsByFaceBase(const InstancePlan& plan) {
  std::vector<std::pair<uint32_t, size_t>> bases;
  for (size_t p = 0; p < plan.parts.size(); ++p) bases.push_back({plan.parts[p].faceBase, p});
  std::sort(bases.begin(), bases.end());
  return bases;
}

std::optional<PartSlot> slotOf(const InstancePlan& plan,
                               const std::vector<std::pair<uint32_t, size_t>>& bases,
                               uint32_t face) {
  const auto after = std::upper_bound(bases.begin(), bases.end(),
                                      std::pair<uint32_t, size_t>(face, plan.parts.size()));
  if (after == bases.begin()) return std::nullopt;
  const size_t part = std::prev(after)->second;
  const uint32_t slot = face - plan.parts[part].faceBase;
  if (slot >= plan.parts[part].faceCount) return std::nullopt;
  return PartSlot{part, slot};
}

// The entity label of the converted shape's face numbered `number`.
const std::string& entityOf(const CadFile& file, const CadImport& import, uint32_t number) {
  for (int k = 1; k <= import.faces.Extent(); ++k)
    if (import.faceNumber(size_t(k - 1)) == number)
      return faceEntityLabel(file, TopoDS::Face(import.faces(k)));
  throw std::logic_error("instances: face " + std::to_string(number) + " is not in the import");
}

glm::dvec3 moved(const gp_Trsf& motion, const glm::dvec3& p) {
  double x = p.x, y = p.y, z = p.z;
  motion.Transforms(x, y, z);
  return {x, y, z};
}

// A normal turned with its copy. (The trimmed mesher gives no normals today, so no test
// reaches this; a mesh with normals must not keep the first place's.)
glm::dvec3 turned(const gp_Trsf& motion, const glm::dvec3& v) {
  gp_XYZ xyz(v.x, v.y, v.z);
  xyz.Multiply(motion.HVectorialPart());  // rigid: the rotation alone
  return {xyz.X(), xyz.Y(), xyz.Z()};
}

// One part's share of the mesh: its faces' positions, its triangles and its vertices.
struct PartMesh {
  std::vector<std::pair<uint32_t, size_t>> positions;  // (position, slot)
  std::vector<uint32_t> triangles;
  std::vector<uint32_t> vertices;  // in first use order
  std::vector<uint32_t> corners;   // per triangle corner: index into `vertices`
};

std::vector<PartMesh> partMeshes(const InstancePlan& plan, const TrimmedMesh& mesh,
                                 const std::vector<uint32_t>& faceNumberOfPosition) {
  const std::vector<std::pair<uint32_t, size_t>> bases = partsByFaceBase(plan);
  std::vector<PartMesh> parts(plan.parts.size());
  constexpr size_t kNone = std::numeric_limits<size_t>::max();
  std::vector<size_t> partOfPosition(faceNumberOfPosition.size(), kNone);
  for (size_t p = 0; p < faceNumberOfPosition.size(); ++p) {
    const std::optional<PartSlot> found = slotOf(plan, bases, faceNumberOfPosition[p]);
    if (!found) continue;
    partOfPosition[p] = found->part;
    parts[found->part].positions.push_back({uint32_t(p), found->slot});
  }
  constexpr uint32_t kUnseen = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> local(mesh.mesh.vertexCount(), kUnseen);  // parts' vertices are their own
  for (size_t t = 0; t < mesh.triangleFace.size(); ++t) {
    const size_t part = partOfPosition[mesh.triangleFace[t]];
    if (part == kNone) continue;
    PartMesh& pm = parts[part];
    pm.triangles.push_back(uint32_t(t));
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = mesh.mesh.indices[3 * t + size_t(c)];
      if (local[v] == kUnseen) {
        local[v] = uint32_t(pm.vertices.size());
        pm.vertices.push_back(v);
      }
      pm.corners.push_back(local[v]);
    }
  }
  return parts;
}

// Each part's faces and where the mesh holds it once, before any copy: the mesher emits faces
// in order and a part's faces are consecutive, so its triangles are one run; its vertices are
// made while its faces are and no other face's triangle uses one (a part welds to nothing), so
// they are one range too (holding the unused ones of collapsed triangles). std::logic_error if
// a change to the mesher breaks either.
std::vector<GlbInstances::Part> placedParts(const InstancePlan& plan,
                                            const std::vector<PartMesh>& parts,
                                            const TriangleMesh& mesh) {
  std::vector<GlbInstances::Part> out(parts.size());
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> partOfVertex(mesh.vertexCount(), kNone);
  for (size_t p = 0; p < parts.size(); ++p) {
    GlbInstances::Part& part = out[p];
    part.faceFirst = plan.parts[p].faceBase;
    part.faceCount = plan.parts[p].faceCount;
    const PartMesh& pm = parts[p];
    if (pm.triangles.empty()) continue;  // its faces all failed
    part.firstTriangle = pm.triangles.front();
    part.triangleCount = uint32_t(pm.triangles.size());
    const auto [low, high] = std::minmax_element(pm.vertices.begin(), pm.vertices.end());
    part.firstVertex = *low;
    part.vertexCount = *high - *low + 1;
    if (pm.triangles.back() - part.firstTriangle + 1 != part.triangleCount)
      throw std::logic_error("instances: part " + std::to_string(p) +
                             "'s triangles are not one run of the mesh");
    for (uint32_t v = *low; v <= *high; ++v) {
      if (partOfVertex[v] != kNone)
        throw std::logic_error("instances: two parts' vertex ranges overlap");
      partOfVertex[v] = uint32_t(p);
    }
  }
  // A triangle uses one part's vertices, and then it is in that part's run, or none.
  for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t p = partOfVertex[mesh.indices[3 * size_t(t)]];
    const bool ownVertices = partOfVertex[mesh.indices[3 * size_t(t) + 1]] == p &&
                             partOfVertex[mesh.indices[3 * size_t(t) + 2]] == p;
    if (!ownVertices || (p != kNone && t - out[p].firstTriangle >= out[p].triangleCount))
      throw std::logic_error("instances: triangle " + std::to_string(t) +
                             " uses a part's vertices from outside the part");
  }
  return out;
}

// The bytes of one vertex and one triangle of `out`, as its arrays hold them.
std::pair<uint64_t, uint64_t> bytesPerVertexAndTriangle(const TrimmedMesh& out) {
  const TriangleMesh& m = out.mesh;
  const auto bytes = [](const auto& vector) { return vector.empty() ? 0 : sizeof(vector[0]); };
  return {bytes(m.positions) + bytes(m.normals) + bytes(m.uvs) + bytes(m.patchIds) +
              bytes(m.positionsDouble) + bytes(m.normalsDouble),
          3 * bytes(m.indices) + bytes(m.trianglePatchIds) + bytes(out.triangleFace) +
              3 * sizeof(glm::dvec2)};  // cornerUv
}

// Room for every copy at once: the vectors grow by the copies' count times the part's size,
// checked against the memory budget first (a board of 10⁵ placed parts multiplies the mesh).
// Listed, only the faces' stats grow (a board's 10⁵ parts of 50 faces: ~0.6 GB of them).
void reserveForCopies(const InstancePlan& plan, const std::vector<PartMesh>& parts,
                      TrimmedMesh& out, CopyPlacement placement) {
  uint64_t vertices = 0, triangles = 0, faces = 0;
  for (const InstanceCopy& copy : plan.copies) {
    vertices += parts[copy.part].vertices.size();
    triangles += parts[copy.part].triangles.size();
    faces += parts[copy.part].positions.size();
  }
  // A face's stats and its number (faceNumberOfPosition).
  const uint64_t faceBytes =
      saturatingMultiply(out.faces.size() + faces, sizeof(TrimmedFaceStats) + sizeof(uint32_t));
  if (placement == CopyPlacement::Listed) {
    requireWithinMemoryBudget(faceBytes, "the faces' stats of " +
                                             std::to_string(plan.copies.size()) +
                                             " placed copies of its parts (" +
                                             std::to_string(out.faces.size() + faces) + " faces)");
    out.faces.reserve(out.faces.size() + faces);
    return;
  }
  const auto [perVertex, perTriangle] = bytesPerVertexAndTriangle(out);
  requireWithinMemoryBudget(
      saturatingAdd(
          saturatingAdd(saturatingMultiply(out.mesh.vertexCount() + vertices, perVertex),
                        saturatingMultiply(out.mesh.triangleCount() + triangles, perTriangle)),
          faceBytes),
      "the mesh with " + std::to_string(plan.copies.size()) + " placed copies of its parts (" +
          std::to_string(out.mesh.triangleCount() + triangles) + " triangles)");
  TriangleMesh& m = out.mesh;
  const auto grow = [](auto& vector, size_t more) {
    if (!vector.empty()) vector.reserve(vector.size() + more);
  };
  for (auto* v : {&m.positions, &m.normals}) grow(*v, vertices);
  grow(m.uvs, vertices);
  grow(m.patchIds, vertices);
  for (auto* v : {&m.positionsDouble, &m.normalsDouble}) grow(*v, vertices);
  grow(m.indices, 3 * triangles);
  grow(m.trianglePatchIds, triangles);
  grow(out.triangleFace, triangles);
  grow(out.cornerUv, 3 * triangles);
  grow(out.faces, faces);
}

// The copy's faces: their stats under its numbers, at new positions (newPosition: the part's
// positions → the copy's).
void appendCopyFaces(const PartMesh& part, const InstanceCopy& copy, TrimmedMesh& out,
                     std::vector<uint32_t>& faceNumberOfPosition,
                     std::vector<uint32_t>& newPosition) {
  for (const auto& [position, slot] : part.positions) {
    newPosition[position] = uint32_t(faceNumberOfPosition.size());
    faceNumberOfPosition.push_back(copy.faceBase + uint32_t(slot));
    TrimmedFaceStats stats = out.faces[position];  // a copy: push_back may move the vector
    stats.faceIndex = copy.faceBase + uint32_t(slot);
    out.faces.push_back(stats);
  }
}

// The copy's vertices and triangles, after appendCopyFaces has given its faces positions.
void appendCopyGeometry(const PartMesh& part, const InstanceCopy& copy, TrimmedMesh& out,
                        const std::vector<uint32_t>& newPosition) {
  TriangleMesh& m = out.mesh;
  const uint32_t base = uint32_t(m.positions.size());
  const bool hasDouble = !m.positionsDouble.empty();
  for (uint32_t v : part.vertices) {
    const glm::dvec3 p =
        moved(copy.motion, hasDouble ? m.positionsDouble[v] : glm::dvec3(m.positions[v]));
    m.positions.push_back(glm::vec3(p));
    if (hasDouble) m.positionsDouble.push_back(p);
    if (!m.normals.empty())
      m.normals.push_back(glm::vec3(turned(copy.motion, glm::dvec3(m.normals[v]))));
    if (!m.normalsDouble.empty())
      m.normalsDouble.push_back(turned(copy.motion, m.normalsDouble[v]));
    if (!m.uvs.empty()) {
      const glm::vec2 uv = m.uvs[v];  // (not a reference into the vector it grows)
      m.uvs.push_back(uv);
    }
    if (!m.patchIds.empty()) m.patchIds.push_back(newPosition[m.patchIds[v]]);
  }
  for (size_t k = 0; k < part.triangles.size(); ++k) {
    const uint32_t t = part.triangles[k];
    for (int c = 0; c < 3; ++c) m.indices.push_back(base + part.corners[3 * k + size_t(c)]);
    out.triangleFace.push_back(newPosition[out.triangleFace[t]]);
    for (int c = 0; c < 3; ++c) {
      const glm::dvec2 uv = out.cornerUv[3 * t + size_t(c)];
      out.cornerUv.push_back(uv);
    }
    if (!m.trianglePatchIds.empty())
      m.trianglePatchIds.push_back(newPosition[m.trianglePatchIds[t]]);
  }
}

}  // namespace

std::vector<CadFaceFailure> copiedFaceFailures(const InstancePlan& plan, const CadFile& file,
                                               const CadImport& import,
                                               const std::vector<CadFaceFailure>& failures) {
  std::vector<CadFaceFailure> copied;
  if (plan.copies.empty() || failures.empty()) return copied;
  const std::vector<std::pair<uint32_t, size_t>> bases = partsByFaceBase(plan);
  for (const CadFaceFailure& failure : failures) {
    const std::optional<PartSlot> found = slotOf(plan, bases, failure.faceIndex);
    if (!found) continue;
    const std::string& entity = entityOf(file, import, failure.faceIndex);
    for (const InstanceCopy& copy : plan.copies) {
      if (copy.part != found->part) continue;
      CadFaceFailure again = failure;
      again.faceIndex = copy.faceBase + uint32_t(found->slot);
      again.label = cadFaceLabel(again.faceIndex, entity);
      again.message = file.path + ": " + again.label + ": " + again.reason;
      copied.push_back(std::move(again));
    }
  }
  return copied;
}

std::vector<CadEdgeWarning> copiedEdgeWarnings(const InstancePlan& plan, const CadFile& file,
                                               const CadImport& import) {
  std::vector<CadEdgeWarning> copied;
  if (plan.copies.empty() || import.warnings.empty()) return copied;
  const std::vector<std::pair<uint32_t, size_t>> bases = partsByFaceBase(plan);
  for (const CadEdgeWarning& warning : import.warnings) {
    const std::optional<PartSlot> found = slotOf(plan, bases, warning.faceIndex);
    if (!found) continue;
    const InstancedPart& part = plan.parts[found->part];
    if (warning.edgeIndex < part.edgeBase || warning.edgeIndex - part.edgeBase >= part.edgeCount)
      throw std::logic_error("instances: a warned edge is not its face's part's");
    const uint32_t edgeSlot = warning.edgeIndex - part.edgeBase;
    const std::string& entity = entityOf(file, import, warning.faceIndex);
    for (const InstanceCopy& copy : plan.copies) {
      if (copy.part != found->part) continue;
      const uint32_t face = copy.faceBase + uint32_t(found->slot);
      copied.push_back(cadEdgeWarning(file.path, face, cadFaceLabel(face, entity),
                                      copy.edgeBase + edgeSlot, warning.gap, warning.tolerance));
    }
  }
  return copied;
}

CopiesSize addInstanceCopies(const InstancePlan& plan, TrimmedMesh& mesh,
                             std::vector<uint32_t>& faceNumberOfPosition, CopyPlacement placement) {
  CopiesSize size;
  if (plan.copies.empty()) return size;
  const std::vector<PartMesh> parts = partMeshes(plan, mesh, faceNumberOfPosition);
  size.parts = placedParts(plan, parts, mesh.mesh);  // before the copies grow the mesh
  // Per position of the converted shape's faces: the copy's own (a part's faces), else itself.
  std::vector<uint32_t> newPosition(faceNumberOfPosition.size());
  std::iota(newPosition.begin(), newPosition.end(), 0u);
  reserveForCopies(plan, parts, mesh, placement);
  for (const InstanceCopy& copy : plan.copies) {
    appendCopyFaces(parts[copy.part], copy, mesh, faceNumberOfPosition, newPosition);
    if (placement == CopyPlacement::InMesh)
      appendCopyGeometry(parts[copy.part], copy, mesh, newPosition);
    size.vertices += parts[copy.part].vertices.size();
    size.triangles += parts[copy.part].triangles.size();
  }
  return size;
}

GlbInstances glbInstancesOf(const InstancePlan& plan, uint64_t vertices, uint64_t triangles,
                            std::vector<GlbInstances::Part> parts) {
  GlbInstances out;
  if (plan.copies.empty()) return out;
  if (parts.size() != plan.parts.size())
    throw std::logic_error("instances: the parts are not the plan's");
  out.vertices = vertices;
  out.triangles = triangles;
  out.parts = std::move(parts);
  for (const InstanceCopy& copy : plan.copies) {
    GlbInstances::Placement placed;
    placed.part = copy.part;
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 3; ++row)
        placed.matrix[size_t(4 * column + row)] = copy.motion.Value(row + 1, column + 1);
    placed.matrix[15] = 1.0;
    placed.faceOffset = int64_t(copy.faceBase) - int64_t(plan.parts[copy.part].faceBase);
    out.placements.push_back(placed);
  }
  return out;
}

}  // namespace tessera
