#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "base/errors.h"
#include "deform/method.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

void checkDistinct(const std::vector<Method>& list) {
  for (std::size_t a = 0; a < list.size(); ++a)
    for (std::size_t b = a + 1; b < list.size(); ++b)
      SOMICAGE_ASSERT(std::strcmp(list[a]->name, list[b]->name) != 0 && list[a]->listOrder != list[b]->listOrder,
                      "every method has its own name and list position");
}

std::vector<Method>& registry() {
  static std::vector<Method> methods = [] {
    std::vector<Method> list{
#define SOMICAGE_METHOD(id) Method(methods::id()),
#include "method_list.inc"
#undef SOMICAGE_METHOD
    };
    std::sort(list.begin(), list.end());
    checkDistinct(list);
    SOMICAGE_ASSERT(!list.empty(), "core/methods holds at least one method");
    return list;
  }();
  return methods;
}

}  // namespace

const std::vector<Method>& allMethods() { return registry(); }

MethodRegistration::MethodRegistration(const MethodDescriptor& descriptor) : descriptor_(&descriptor) {
  std::vector<Method>& list = registry();
  list.insert(std::upper_bound(list.begin(), list.end(), Method(descriptor)), Method(descriptor));
  checkDistinct(list);
}

MethodRegistration::~MethodRegistration() {
  std::vector<Method>& list = registry();
  list.erase(std::remove(list.begin(), list.end(), Method(*descriptor_)), list.end());
}

Method::Method() : descriptor_(&allMethods().front().descriptor()) {}

std::string methodName(Method method) { return method->name; }

std::vector<MethodOptionFlag> methodOptionFlags() {
  std::vector<MethodOptionFlag> flags;
  for (Method m : allMethods())
    for (const MethodOptionSpec& o : m->options)
      flags.push_back({std::string("--") + o.key, &o, std::string(o.help) + "; " + m->name + " only"});
  return flags;
}

std::optional<Method> findMethod(const std::string& name) {
  for (Method m : allMethods())
    if (name == m->name) return m;
  return std::nullopt;
}

std::string methodNameList() {
  std::string list;
  const std::vector<Method>& methods = allMethods();
  for (std::size_t k = 0; k < methods.size(); ++k)
    list += (k == 0 ? "" : k + 1 == methods.size() ? " or " : ", ") + std::string(methods[k]->name);
  return list;
}

Method parseMethod(const std::string& name) {
  if (const std::optional<Method> method = findMethod(name)) return *method;
  throw InputError("--method", -1, "unknown method '" + name + "'", "use " + methodNameList());
}

bool readsParameter(Method method, DeformParameter parameter) { return (method->parameters & parameter) != 0; }

std::string methodsReading(DeformParameter parameter) {
  std::vector<std::string> names;
  for (Method m : allMethods())
    if (readsParameter(m, parameter)) names.emplace_back(m->name);
  if (names.size() == 1) return names.front() + " only";
  std::string list;
  for (std::size_t k = 0; k < names.size(); ++k)
    list += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return list.empty() ? "no method" : list;
}

CoordinateLayout coordinateLayout(Method method, const Cage& cage, int layoutVertices) {
  return method->layout(cage.dim(), layoutVertices >= 0 ? layoutVertices : cage.numVertices(), cage.numFaces());
}

}  // namespace somicage
