#!/usr/bin/env python3
"""Which includes of a folder's files look unused, and which names a file uses through another file's includes
(a heuristic: names are matched as words, not resolved by a compiler). For each #include: is any name its header
declares at namespace scope (types, functions, aliases, constants, enumerators, macros; for a standard header, a list
of its names) used in the file? For each name a file uses whose header is known: is that header included directly,
or by the .cpp's own header? Each finding is a place to look, then confirm by removing or adding the include and
building (docs/editor.md, "Includes"). Prints the findings; always exits 0.

Usage: include_audit.py REPOSITORY_ROOT FOLDER [project]   (e.g. . app/editor project)
"""
import os, re, sys, glob, collections

ROOT = sys.argv[1]
FOLDER = sys.argv[2]  # e.g. app/editor
INCLUDE_DIRS = [os.path.join(ROOT, d) for d in ["app/editor", "app", "core", "render", "tests"]]

STD = {
 "string": "std::string std::to_string std::stoi std::stod std::stol std::getline std::stoul std::stof std::char_traits",
 "vector": "std::vector",
 "algorithm": "std::min std::max std::sort std::find std::find_if std::clamp std::any_of std::all_of std::none_of std::count std::count_if std::remove_if std::reverse std::fill std::copy std::transform std::unique std::lower_bound std::upper_bound std::max_element std::min_element std::minmax std::stable_sort std::nth_element std::partial_sort std::equal std::remove std::replace std::for_each std::copy_if std::rotate std::search std::mismatch std::binary_search std::find_if_not std::minmax_element std::set_difference std::includes std::is_sorted std::fill_n std::generate std::replace_if std::stable_partition std::partition",
 "optional": "std::optional std::nullopt std::make_optional std::bad_optional_access",
 "memory": "std::shared_ptr std::unique_ptr std::make_shared std::make_unique std::weak_ptr std::enable_shared_from_this std::static_pointer_cast std::dynamic_pointer_cast",
 "cmath": "std::sqrt std::pow std::sin std::cos std::atan2 std::isfinite std::isnan std::isinf std::floor std::ceil std::round std::log std::exp std::fabs std::hypot std::fmod std::tan std::acos std::asin std::atan std::log10 std::lround std::trunc std::copysign M_PI std::log2 std::fmin std::fmax std::signbit std::exp2 std::cbrt std::lrint std::abs std::nextafter std::llround std::remainder",
 "cstdio": "std::printf std::fprintf std::snprintf std::fflush stderr stdout std::FILE std::fopen std::fclose std::fwrite std::fread std::puts std::fputs std::remove std::rename std::sscanf std::fgets std::perror std::vsnprintf std::fputc std::putchar",
 "utility": "std::move std::pair std::swap std::exchange std::forward std::make_pair std::as_const std::declval std::index_sequence",
 "functional": "std::function std::ref std::cref std::hash std::bind std::invoke std::greater std::less",
 "filesystem": "std::filesystem",
 "system_error": "std::error_code std::system_error std::errc std::generic_category std::system_category",
 "limits": "std::numeric_limits",
 "cstdint": "std::uint64_t std::int64_t std::uint32_t std::int32_t std::uint8_t std::int8_t std::uint16_t std::int16_t uint64_t int64_t uint32_t int32_t uint8_t uint16_t int16_t int8_t UINT64_MAX INT64_MAX std::uintptr_t uintptr_t",
 "map": "std::map std::multimap",
 "exception": "std::exception std::exception_ptr std::current_exception std::rethrow_exception std::terminate std::make_exception_ptr",
 "cstdlib": "std::getenv std::exit std::strtod std::strtol std::strtoul std::atoi std::system std::free std::malloc EXIT_FAILURE EXIT_SUCCESS std::abort std::atof std::strtoll std::setenv setenv unsetenv std::rand std::qsort mkdtemp mkstemp",
 "chrono": "std::chrono",
 "fstream": "std::ifstream std::ofstream std::fstream",
 "new": "std::bad_alloc std::nothrow",
 "mutex": "std::mutex std::lock_guard std::unique_lock std::scoped_lock std::once_flag std::call_once std::recursive_mutex",
 "cstddef": "std::size_t std::ptrdiff_t std::nullptr_t std::byte offsetof",
 "atomic": "std::atomic",
 "array": "std::array",
 "tuple": "std::tuple std::tie std::make_tuple std::apply std::forward_as_tuple std::tuple_size",
 "thread": "std::thread std::this_thread",
 "iterator": "std::begin std::end std::size std::next std::prev std::distance std::back_inserter std::advance std::data std::rbegin std::make_move_iterator std::istreambuf_iterator std::inserter std::ostream_iterator std::empty std::ssize",
 "ctime": "std::time std::localtime std::strftime std::tm std::time_t localtime_r std::mktime std::gmtime std::difftime time_t gmtime_r",
 "stdexcept": "std::runtime_error std::logic_error std::invalid_argument std::out_of_range std::range_error std::domain_error std::length_error",
 "sstream": "std::ostringstream std::istringstream std::stringstream",
 "set": "std::set std::multiset",
 "unordered_map": "std::unordered_map",
 "unordered_set": "std::unordered_set",
 "iostream": "std::cout std::cerr std::cin std::clog",
 "deque": "std::deque",
 "cstring": "std::strlen std::strcmp std::memcpy std::memset std::strerror std::strncmp std::memcmp std::strchr std::strncpy std::strstr strerror std::strrchr",
 "condition_variable": "std::condition_variable",
 "cerrno": "errno EINTR ENOENT EEXIST EACCES",
 "cctype": "std::isdigit std::isspace std::tolower std::toupper std::isalpha std::isalnum std::isprint std::isxdigit std::ispunct std::isupper std::islower",
 "unistd.h": "getpid access unlink isatty fsync sysconf getuid close pid_t rmdir readlink",
 "sys/stat.h": "stat S_ISDIR chmod mkdir S_IRUSR",
 "signal.h": "kill SIGTERM signal sigaction SIGKILL SIGINT",
 "stdlib.h": "mkdtemp mkstemp setenv unsetenv getenv",
 "omp.h": "omp_",
 "Eigen/Core": "Eigen::",
 "Eigen/Geometry": "Eigen::AngleAxisd Eigen::Quaterniond Eigen::Affine3d Eigen::Isometry3d Eigen::AngleAxisf .cross( Eigen::AngleAxis Eigen::Quaternion Eigen::Affine Eigen::Isometry Eigen::Transform Eigen::Hyperplane Eigen::AlignedBox .eulerAngles( Eigen::Translation .homogeneous( .hnormalized( Eigen::Projective",
 "Eigen/Dense": ".inverse( .determinant( .partialPivLu( .fullPivLu( .ldlt( .llt( JacobiSVD BDCSVD SelfAdjointEigenSolver .colPivHouseholderQr( .householderQr( .cross( Eigen::AngleAxis Eigen::Quaternion .jacobiSvd( .solve( Eigen::PartialPivLU Eigen::LDLT Eigen::LLT",
 "imgui.h": "ImGui:: ImVec2 ImVec4 ImU32 IM_COL32 ImDrawList ImGuiKey ImGuiWindowFlags ImGuiCol ImGuiIO ImGuiStyle ImGuiCond ImGuiTableFlags ImGuiInputTextFlags ImGuiTreeNodeFlags ImGuiMouseButton ImGuiHoveredFlags ImFont ImGuiStyleVar ImGuiSelectableFlags ImGuiComboFlags ImGuiSliderFlags ImGuiFocusedFlags ImDrawData ImGuiViewport ImGuiID ImGuiDir ImGuiPopupFlags ImGuiTabBarFlags ImGuiInputTextCallbackData ImGuiMouseCursor ImTextureID",
 "imgui_stdlib.h": "InputText( InputTextWithHint( InputTextMultiline(",
 "GLFW/glfw3.h": "glfw GLFW_ GLFWwindow",
 "stb_image_write.h": "stbi_",
 "imgui_impl_opengl3.h": "ImGui_ImplOpenGL3_",
 "imgui_impl_glfw.h": "ImGui_ImplGlfw_",
 "gtest/gtest.h": "TEST EXPECT_ ASSERT_ ::testing ADD_FAILURE GTEST_SKIP",
}
STD = {k: v.split() for k, v in STD.items()}

def strip(text):
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    text = re.sub(r'//[^\n]*', '', text)
    text = re.sub(r'R"\((.*?)\)"', '""', text, flags=re.S)
    text = re.sub(r'"(\\.|[^"\\\n])*"', '""', text)
    text = re.sub(r"'(\\.|[^'\\\n])'", "' '", text)
    return text

def resolve(inc, frm):
    for d in [os.path.dirname(frm)] + INCLUDE_DIRS:
        p = os.path.join(d, inc)
        if os.path.exists(p): return os.path.normpath(p)
    return None

KW = set("if for while switch return sizeof static_cast const_cast reinterpret_cast dynamic_cast decltype alignof noexcept operator template typename namespace using public private protected class struct enum union void int bool double float char long short unsigned signed auto const constexpr inline static explicit virtual override final friend extern default delete new this throw try catch nullptr true false".split())

_decl_cache = {}
def declared(path):
    """Names a header declares at namespace scope (types, functions, aliases, constants, macros)."""
    if path in _decl_cache: return _decl_cache[path]
    text = open(path, errors='replace').read()
    names = set(re.findall(r'^\s*#\s*define\s+(\w+)', text, re.M))
    t = strip(text)
    names |= set(re.findall(r'\b(?:struct|class|union)\s+(?:\[\[\w+\]\]\s+)?(\w+)\s*(?:final\s*)?[:{;]', t))
    names |= set(re.findall(r'\benum\s+(?:class\s+|struct\s+)?(\w+)', t))
    names |= set(re.findall(r'\busing\s+(\w+)\s*=', t))
    names |= set(re.findall(r'\btypedef\b[^;]*?\b(\w+)\s*;', t))
    # top-level lines (no indentation): function declarations and variables
    for line in t.split('\n'):
        if not line or line[0] in ' \t#}': continue
        m = re.match(r'^(?:template\s*<[^>]*>\s*)?(?:(?:inline|static|constexpr|extern|const|friend|explicit)\s+)*[\w:<>,\s\*&]+?[\s\*&](~?\w+)\s*\(', line)
        if m and m.group(1) not in KW: names.add(m.group(1))
        m = re.match(r'^(?:inline\s+|static\s+|extern\s+)*(?:constexpr|const)\s+[\w:<>,\s\*&]+?\b(\w+)\s*(?:=|\{|\[|;)', line)
        if m and m.group(1) not in KW: names.add(m.group(1))
    # enum values at any indentation inside `enum ... { ... }`
    for body in re.findall(r'\benum\b[^{;]*\{([^}]*)\}', t):
        for v in re.findall(r'\b([A-Za-z_]\w*)\s*(?:=[^,]*)?(?:,|$)', body):
            names.add(v)
    names.discard('')
    _decl_cache[path] = names
    return names

def includes(text):
    return re.findall(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', text, re.M)

def uses(body, sym):
    if sym.startswith('.') or sym.endswith('(') or sym.endswith('::') or sym.endswith('_'):
        return sym in body
    return re.search(r'(?<![\w])' + re.escape(sym) + r'\b', body) is not None if '::' not in sym else re.search(re.escape(sym) + r'\b', body) is not None

files = sorted(glob.glob(os.path.join(ROOT, FOLDER, '**', '*.h'), recursive=True) +
               glob.glob(os.path.join(ROOT, FOLDER, '**', '*.cpp'), recursive=True))
for f in files:
    raw = open(f, errors='replace').read()
    body = re.sub(r'^\s*#\s*include[^\n]*', '', strip(raw), flags=re.M)
    rel = os.path.relpath(f, ROOT)
    own = os.path.splitext(f)[0] + '.h'
    for kind, inc in includes(raw):
        if kind == '<':
            syms = STD.get(inc)
            if syms is None:
                print(f"{rel}: <{inc}>: no symbol list"); continue
            if not any(uses(body, s) for s in syms):
                print(f"{rel}: <{inc}> UNUSED?")
        else:
            p = resolve(inc, f)
            if p is None:
                print(f"{rel}: \"{inc}\": not found"); continue
            if os.path.normpath(p) == os.path.normpath(own) and f.endswith('.cpp'):
                continue
            names = declared(p)
            if inc == "methods/method_descriptors.h": names = names | {"methods::"}  # generated: methods::NAME()
            used = [n for n in names if uses(body, n)]
            if not used:
                print(f"{rel}: \"{inc}\" UNUSED? ({len(names)} names: {' '.join(sorted(names)[:8])})")
    # missing std includes: symbol used, header not included directly (a .cpp may use its own header's)
    direct = {i for k, i in includes(raw)}
    SPLIT = {'deformation.cpp', 'edits.cpp', 'document_files.cpp', 'scene_loading.cpp'}
    if os.path.basename(f) in SPLIT: own = os.path.join(ROOT, 'app/editor/model/app_state.h')
    if f.endswith('.cpp') and os.path.exists(own):
        direct |= {i for k, i in includes(open(own).read())}
    for h, syms in STD.items():
        if h in direct or h in ('imgui_stdlib.h', 'gtest/gtest.h', 'stdlib.h', 'Eigen/Geometry', 'Eigen/Dense', 'unistd.h', 'sys/stat.h', 'signal.h', 'cerrno', 'cstddef', 'cstdint'):
            continue
        if h == 'Eigen/Core' and 'Eigen/Dense' in direct: continue
        hit = [s for s in syms if uses(body, s) and not (s == 'std::abs' or s == 'std::size' or s=='std::remove' or s=='std::empty' or s=='std::data')]
        if hit:
            print(f"{rel}: MISSING <{h}> for {' '.join(hit[:4])}")

# ---- project symbols used without their header (transitive reliance) ----
# Words that are a declared name somewhere but, in app/editor, members, locals or other libraries' names.
NOT_NAMES = {'Clock', 'precompute', 'atan', 'Text', 'Checkbox', 'Combo', 'redo', 'undo', 'Mesh', 'panelWidth',
             'tooltip'}
if len(sys.argv) > 3 and sys.argv[3] == 'project':
    headers = []
    for d in ['app/editor', 'core', 'render', 'app']:
        headers += glob.glob(os.path.join(ROOT, d, '**', '*.h'), recursive=True)
    headers = sorted(set(os.path.normpath(h) for h in headers))
    owner = collections.defaultdict(set)
    for h in headers:
        for n in declared(h):
            if len(n) > 3 and n not in KW: owner[n].add(h)
    unique = {n: next(iter(hs)) for n, hs in owner.items() if len(hs) == 1}
    OWN = {'deformation.cpp': 'model/app_state.h', 'edits.cpp': 'model/app_state.h', 'document_files.cpp': 'model/app_state.h', 'scene_loading.cpp': 'model/app_state.h'}
    for f in files:
        raw = open(f, errors='replace').read()
        body = re.sub(r'^\s*#\s*include[^\n]*', '', strip(raw), flags=re.M)
        rel = os.path.relpath(f, ROOT)
        direct = set()
        for k, i in includes(raw):
            p = resolve(i, f)
            if p: direct.add(p)
        own = os.path.splitext(f)[0] + '.h'
        if os.path.basename(f) in OWN: own = os.path.join(ROOT, 'app/editor', OWN[os.path.basename(f)])
        if f.endswith('.cpp') and os.path.exists(own):
            direct.add(os.path.normpath(own))
            for k, i in includes(open(own).read()):
                p = resolve(i, own)
                if p: direct.add(p)
        direct.add(os.path.normpath(f))
        missing = collections.defaultdict(list)
        idents = set(re.findall(r'\b[A-Za-z_]\w*\b', body))
        for n in idents - NOT_NAMES:
            h = unique.get(n)
            if h and h not in direct:
                missing[h].append(n)
        for h, ns in sorted(missing.items()):
            print(f"{rel}: PROJECT-MISSING \"{os.path.relpath(h, ROOT)}\" for {' '.join(sorted(ns)[:5])}")
