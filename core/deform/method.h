// Deformation methods as descriptors, and the registry that lists them. Everything that differs between methods
// (names, the layout of the coordinate matrix C, the precompute, the memory it takes) is in the method's
// descriptor, one file in core/methods/ (docs/engine.md, "Adding a method"); callers ask the registry instead of
// switching on a method.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/progress.h"
#include "deform/coordinate_layout.h"
#include "deform/frame_finish.h"
#include "geometry/cage.h"

namespace somicage {

class CageDeformer;
struct DeformParams;
struct PrecomputeOptions;

// The fields of DeformParams a method reads (MethodDescriptor::parameters, a bit set); it ignores the others.
enum DeformParameter : unsigned {
  kParamBlend = 1u << 0,         // blend (--variant, --blend)
  kParamNu = 1u << 1,            // nu
  kParamGamma = 1u << 2,         // gamma
  kParamTractionFix = 1u << 3,   // tractionCorrection
  kParamCorotational = 1u << 4,  // corotational
  kParamBulging = 1u << 5,       // bulging (deform_choices.h)
  kParamNormals = 1u << 6,       // normals (deform_choices.h)
};

// A precompute option of a method's own (MethodDescriptor::options): text in PrecomputeOptions::methodOptions
// under `key`, which the front ends fill from their own spelling of it (the CLI's --KEY, Python's KEY= with - as _).
struct MethodOptionSpec {
  const char* key;    // "tets"
  const char* value;  // what it holds, for help texts: "FILE"
  const char* help;   // one line: "a MEDIT .mesh volume mesh of the cage (default: tetrahedralize it)"
  // Throws InputError when `value` is not one the option takes (callers name their own option); null: any text.
  void (*check)(const std::string& value) = nullptr;
};

// The per-element coordinate fields a method can show (MethodDescriptor::fields; coordinate_fields.h, the editor's
// "field" quantity): a cage vertex's T_i n_i and a face's K_j n_j at the method's nu.
enum ElementField : unsigned {
  kFieldVertex = 1u << 0,
  kFieldFace = 1u << 1,
};

struct MethodDescriptor {
  const char* name;         // the command line's --method, session files, Python: "somigliana"
  const char* displayName;  // the editor's menus and labels: "Somigliana"
  const char* description;  // one line for help texts and tooltips (the CLI's help, Blender): what it is, its source
  int listOrder;            // position in lists (help text, menus): ascending
  unsigned parameters;      // the DeformParameter bits it reads
  bool reproducesOutside;   // reproduces a still cage outside it too (no exterior rule needed)
  // Needs a volume mesh of the rest cage (volume_mesh.h: PrecomputeOptions::volumeMesh, or one made from its
  // options): the Phong deformer. Its layout's "vertices" are then that mesh's vertices.
  bool needsVolumeMesh;
  std::vector<MethodOptionSpec> options;  // its own precompute options (PrecomputeOptions::methodOptions)
  // Throws InputError naming the parameter ("nu") when params are out of range for this method (at least
  // validateDeformParams, deformer.h; a method may refuse more, e.g. nu = 0.5 for BEM).
  void (*validateParams)(const DeformParams& params);

  // The columns of C for a cage of dimension dim (coordinate_layout.h); numVertices: the cage's, or its volume
  // mesh's for a method that needs one.
  CoordinateLayout (*layout)(int dim, int numVertices, int numFaces);
  // Bytes the precompute holds besides C at its peak (copies, per-thread buffers, diagnostics) for `points`
  // points with `threads` OpenMP threads (> 0).
  std::size_t (*workingBytes)(const CoordinateLayout& layout, int dim, std::size_t points, bool floatStorage,
                              int threads);
  // Precomputes the coordinates of points (#P by d) in the rest cage. Throws Cancelled if progress says stop.
  std::unique_ptr<CageDeformer> (*precompute)(const Cage& restCage, const Eigen::MatrixXd& points,
                                              const PrecomputeOptions& options, const ProgressCallback& progress);
  // How its frames finish (frame_finish.h): what its FrameWeights::finish is, and what every evaluator switches on.
  FrameFinish finish = FrameFinish::Linear;
  unsigned fields = 0;  // the ElementField bits it can show
};

// A method: a handle on its descriptor in the registry (cheap to copy, ordered by listOrder).
class Method {
 public:
  Method();                                                                 // the registry's first method (Somigliana)
  Method(const MethodDescriptor& descriptor) : descriptor_(&descriptor) {}  // NOLINT: a descriptor is a method

  const MethodDescriptor& descriptor() const { return *descriptor_; }
  const MethodDescriptor* operator->() const { return descriptor_; }

  friend bool operator==(Method a, Method b) { return a.descriptor_ == b.descriptor_; }
  friend bool operator!=(Method a, Method b) { return a.descriptor_ != b.descriptor_; }
  friend bool operator<(Method a, Method b) { return a->listOrder < b->listOrder; }

 private:
  const MethodDescriptor* descriptor_;
};

// Every registered method, by listOrder: core/methods/*_method.cpp, and those registered at run time.
const std::vector<Method>& allMethods();

// Adds a method for the registration's lifetime (a test's throw-away method, a plug-in): every front end that asks
// the registry lists it. Not thread-safe: register before front ends run. The descriptor must outlive it.
class MethodRegistration {
 public:
  explicit MethodRegistration(const MethodDescriptor& descriptor);
  ~MethodRegistration();
  MethodRegistration(const MethodRegistration&) = delete;
  MethodRegistration& operator=(const MethodRegistration&) = delete;

 private:
  const MethodDescriptor* descriptor_;
};

std::string methodName(Method method);  // descriptor().name: "somigliana", "green", "mvc"
std::optional<Method> findMethod(const std::string& name);
// Throws InputError("--method", ...) naming the known methods when there is none of that name.
Method parseMethod(const std::string& name);
// "somigliana, green or mvc": for help texts and hints.
std::string methodNameList();

// Whether the method reads that parameter (MethodDescriptor::parameters).
bool readsParameter(Method method, DeformParameter parameter);
// The names of the methods that read it, for help texts: "somigliana only", "somigliana and bem".
std::string methodsReading(DeformParameter parameter);

// A method's option as a command-line flag, for every front end's parser and help text: "--tets", its spec, and
// "a MEDIT .mesh volume mesh of the cage (...); phong only".
struct MethodOptionFlag {
  std::string flag;
  const MethodOptionSpec* spec;
  std::string help;
};
// Every registered method's options, in registry order.
std::vector<MethodOptionFlag> methodOptionFlags();

// The layout of C that `method` stores for a cage, and for a method that needs a volume mesh, that mesh's vertex
// count (layoutVertices: the cage's own otherwise).
CoordinateLayout coordinateLayout(Method method, const Cage& cage, int layoutVertices = -1);

}  // namespace somicage
