// The EGL backend: an OpenGL 3.3 core context without any surface (EGL_KHR_surfaceless_context;
// drawing goes to framebuffer objects), on one EGL display per process chosen by the rule below.
// libEGL (Debian's libglvnd one, which hands the work to Mesa's libEGL_mesa or a GPU vendor's
// EGL) is opened with dlopen when the first context is made, like OSMesa, so that commands which
// do not render never load it.
//
// Which display, from URDFSNAP_EGL_DEVICE:
//   unset, "" or "auto": the first EGL device in libEGL's order (EGL_EXT_device_enumeration)
//     that is not Mesa's software device and on which a display initialises with desktop OpenGL,
//     through EGL's device platform (EGL_EXT_platform_device): a GPU where one is exposed. When
//     there is none (no /dev/dri, as in containers and CI), or LIBGL_ALWAYS_SOFTWARE is set,
//     Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), which is llvmpipe on the CPU.
//   "software": Mesa's software device (EGL_MESA_device_software, llvmpipe) even where a GPU is.
//   a number N: the N-th device of libEGL's list (from 0).
//   a path such as /dev/dri/renderD129: the device with that DRM render node or device file.
#include "gl/internal/gl_api.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "gl/internal/gl_backends.h"
#include "common/shared_library.h"

namespace urdfsnap::gl {

namespace {

constexpr char kDeviceVariable[] = "URDFSNAP_EGL_DEVICE";

// The EGL entry points used: core ones with dlsym, extension ones through eglGetProcAddress
// (null when libEGL lacks the extension).
struct EglLibrary {
  decltype(&eglGetProcAddress) get_proc_address = nullptr;
  decltype(&eglGetError) get_error = nullptr;
  decltype(&eglQueryString) query_string = nullptr;
  decltype(&eglInitialize) initialize = nullptr;
  decltype(&eglBindAPI) bind_api = nullptr;
  decltype(&eglChooseConfig) choose_config = nullptr;
  decltype(&eglCreateContext) create_context = nullptr;
  decltype(&eglDestroyContext) destroy_context = nullptr;
  decltype(&eglMakeCurrent) make_current = nullptr;
  decltype(&eglGetCurrentContext) get_current_context = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;  // EGL_EXT_platform_base
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;               // EGL_EXT_device_enumeration
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;    // EGL_EXT_device_query
};

// The display every context of the process is made on, initialised once, never terminated.
struct EglDisplay {
  EglLibrary egl;
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string label;  // "surfaceless" or "device N: NAME"
};

// "EGL_BAD_MATCH" for EGL_BAD_MATCH, the hexadecimal code for others.
std::string ErrorName(EGLint code) {
  static const std::pair<EGLint, const char*> names[] = {
      {EGL_SUCCESS, "EGL_SUCCESS"},
      {EGL_NOT_INITIALIZED, "EGL_NOT_INITIALIZED"},
      {EGL_BAD_ACCESS, "EGL_BAD_ACCESS"},
      {EGL_BAD_ALLOC, "EGL_BAD_ALLOC"},
      {EGL_BAD_ATTRIBUTE, "EGL_BAD_ATTRIBUTE"},
      {EGL_BAD_CONFIG, "EGL_BAD_CONFIG"},
      {EGL_BAD_CONTEXT, "EGL_BAD_CONTEXT"},
      {EGL_BAD_CURRENT_SURFACE, "EGL_BAD_CURRENT_SURFACE"},
      {EGL_BAD_DISPLAY, "EGL_BAD_DISPLAY"},
      {EGL_BAD_MATCH, "EGL_BAD_MATCH"},
      {EGL_BAD_NATIVE_PIXMAP, "EGL_BAD_NATIVE_PIXMAP"},
      {EGL_BAD_NATIVE_WINDOW, "EGL_BAD_NATIVE_WINDOW"},
      {EGL_BAD_PARAMETER, "EGL_BAD_PARAMETER"},
      {EGL_BAD_SURFACE, "EGL_BAD_SURFACE"},
      {EGL_CONTEXT_LOST, "EGL_CONTEXT_LOST"},
      {EGL_BAD_DEVICE_EXT, "EGL_BAD_DEVICE_EXT"},
  };
  for (const auto& [value, name] : names) {
    if (value == code) return name;
  }
  std::ostringstream hex;
  hex << "EGL error 0x" << std::hex << code;
  return hex.str();
}

// Whether the space-separated list `words` (may be null) has `word`.
bool HasWord(const char* words, const char* word) {
  if (!words) return false;
  std::istringstream in(words);
  std::string w;
  while (in >> w) {
    if (w == word) return true;
  }
  return false;
}

EglLibrary OpenEgl() {
  const SharedLibrary library(URDFSNAP_EGL_LIBRARY,
                              "install Debian's libegl1, libegl-mesa0 and libgl1-mesa-dri");
  EglLibrary egl;
  egl.get_proc_address = library.Get<decltype(egl.get_proc_address)>("eglGetProcAddress");
  egl.get_error = library.Get<decltype(egl.get_error)>("eglGetError");
  egl.query_string = library.Get<decltype(egl.query_string)>("eglQueryString");
  egl.initialize = library.Get<decltype(egl.initialize)>("eglInitialize");
  egl.bind_api = library.Get<decltype(egl.bind_api)>("eglBindAPI");
  egl.choose_config = library.Get<decltype(egl.choose_config)>("eglChooseConfig");
  egl.create_context = library.Get<decltype(egl.create_context)>("eglCreateContext");
  egl.destroy_context = library.Get<decltype(egl.destroy_context)>("eglDestroyContext");
  egl.make_current = library.Get<decltype(egl.make_current)>("eglMakeCurrent");
  egl.get_current_context = library.Get<decltype(egl.get_current_context)>("eglGetCurrentContext");
  // client extensions, of libEGL itself rather than of a display (EGL_EXT_client_extensions)
  const char* client = egl.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client || !*client) {
    // libglvnd's libEGL without a vendor library (its client extensions are the vendors')
    throw Error(std::string(URDFSNAP_EGL_LIBRARY) +
                " finds no EGL driver; install Debian's libegl-mesa0 and libgl1-mesa-dri");
  }
  if (!HasWord(client, "EGL_EXT_platform_base")) {
    throw Error(std::string(URDFSNAP_EGL_LIBRARY) + " lacks EGL_EXT_platform_base (client extensions: " +
                (client ? client : "none") + ")");
  }
  egl.get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      egl.get_proc_address("eglGetPlatformDisplayEXT"));
  if (!egl.get_platform_display) {
    throw Error(std::string(URDFSNAP_EGL_LIBRARY) + " has no eglGetPlatformDisplayEXT");
  }
  if (HasWord(client, "EGL_EXT_device_enumeration") && HasWord(client, "EGL_EXT_device_query")) {
    egl.query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl.get_proc_address("eglQueryDevicesEXT"));
    egl.query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        egl.get_proc_address("eglQueryDeviceStringEXT"));
  }
  return egl;
}

struct Device {
  EGLDeviceEXT handle;
  std::string name;  // "software", a DRM file, or "unnamed"
  bool software;
};

// libEGL's devices, in its order; none without EGL_EXT_device_enumeration.
std::vector<Device> ListDevices(const EglLibrary& egl) {
  EGLint count = 0;
  if (!egl.query_devices || !egl.query_device_string || !egl.query_devices(0, nullptr, &count)) {
    return {};
  }
  std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count));
  if (!egl.query_devices(count, handles.data(), &count)) return {};
  handles.resize(static_cast<size_t>(count));
  std::vector<Device> devices;
  for (EGLDeviceEXT handle : handles) {
    const char* extensions = egl.query_device_string(handle, EGL_EXTENSIONS);
    Device device{handle, "unnamed", HasWord(extensions, "EGL_MESA_device_software")};
    const char* file = nullptr;
    if (HasWord(extensions, "EGL_EXT_device_drm_render_node")) {
      file = egl.query_device_string(handle, EGL_DRM_RENDER_NODE_FILE_EXT);
    }
    if (!file && HasWord(extensions, "EGL_EXT_device_drm")) {
      file = egl.query_device_string(handle, EGL_DRM_DEVICE_FILE_EXT);
    }
    if (device.software) {
      device.name = "software";
    } else if (file) {
      device.name = file;
    }
    devices.push_back(device);
  }
  return devices;
}

std::string ListText(const std::vector<Device>& devices) {
  if (devices.empty()) return "libEGL lists no devices";
  std::string text = "libEGL lists " + std::to_string(devices.size()) +
                     (devices.size() == 1 ? " device:" : " devices:");
  for (size_t i = 0; i < devices.size(); ++i) {
    text += (i ? ", " : " ") + std::to_string(i) + " " + devices[i].name;
  }
  return text;
}

// Initialises the display of `platform` and `native`; returns it, or throws saying why it
// cannot serve an OpenGL 3.3 core context without a surface.
EGLDisplay OpenDisplay(const EglLibrary& egl, EGLenum platform, void* native) {
  EGLDisplay display = egl.get_platform_display(platform, native, nullptr);
  if (display == EGL_NO_DISPLAY) {
    throw Error("eglGetPlatformDisplayEXT failed (" + ErrorName(egl.get_error()) + ")");
  }
  EGLint major = 0, minor = 0;
  if (!egl.initialize(display, &major, &minor)) {
    throw Error("eglInitialize failed (" + ErrorName(egl.get_error()) +
                "; Mesa's drivers are in Debian's libgl1-mesa-dri)");
  }
  const char* apis = egl.query_string(display, EGL_CLIENT_APIS);
  if (!HasWord(apis, "OpenGL")) {
    throw Error(std::string("no desktop OpenGL (client APIs: ") + (apis ? apis : "none") + ")");
  }
  const char* extensions = egl.query_string(display, EGL_EXTENSIONS);
  if (!HasWord(extensions, "EGL_KHR_surfaceless_context")) {
    throw Error("no EGL_KHR_surfaceless_context");
  }
  // context versions and profiles: EGL 1.5, or EGL_KHR_create_context before it
  if (major == 1 && minor < 5 && !HasWord(extensions, "EGL_KHR_create_context")) {
    throw Error("EGL " + std::to_string(major) + "." + std::to_string(minor) +
                " without EGL_KHR_create_context");
  }
  return display;
}

bool SoftwareForced() {
  // Mesa's own switch (env_var_as_boolean): 1, true, y, yes
  const char* value = std::getenv("LIBGL_ALWAYS_SOFTWARE");
  if (!value) return false;
  const std::string v = value;
  return v == "1" || v == "true" || v == "y" || v == "yes";
}

// The display the rule in this file's header comment picks.
EglDisplay SelectDisplay(const EglLibrary& egl) {
  const char* variable = std::getenv(kDeviceVariable);
  const std::string choice = variable && *variable ? variable : "auto";
  const std::vector<Device> devices = ListDevices(egl);
  auto open_device = [&](size_t i) {
    return EglDisplay{egl, OpenDisplay(egl, EGL_PLATFORM_DEVICE_EXT, devices[i].handle),
                      "device " + std::to_string(i) + ": " + devices[i].name};
  };

  if (choice == "auto") {
    std::string skipped;  // hardware devices that did not serve, for the error below
    for (size_t i = 0; i < devices.size() && !SoftwareForced(); ++i) {
      if (devices[i].software) continue;
      try {
        return open_device(i);
      } catch (const Error& e) {
        skipped += "; device " + std::to_string(i) + " (" + devices[i].name + "): " + e.what();
      }
    }
    const char* client = egl.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    try {
      if (!HasWord(client, "EGL_MESA_platform_surfaceless")) {
        throw Error("libEGL lacks EGL_MESA_platform_surfaceless");
      }
      return EglDisplay{egl, OpenDisplay(egl, EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY),
                        "surfaceless"};
    } catch (const Error& e) {
      throw Error(std::string("surfaceless platform: ") + e.what() + skipped);
    }
  }

  std::optional<size_t> index;
  if (choice == "software") {
    for (size_t i = 0; i < devices.size() && !index; ++i) {
      if (devices[i].software) index = i;
    }
  } else if (choice.find_first_not_of("0123456789") == std::string::npos && choice.size() < 4) {
    if (std::stoul(choice) < devices.size()) index = std::stoul(choice);
  } else if (choice.front() == '/') {
    for (size_t i = 0; i < devices.size() && !index; ++i) {
      if (devices[i].name == choice) index = i;
    }
  } else {
    throw Error(std::string(kDeviceVariable) + "=" + choice +
                ": expected auto, software, a device number or a /dev/dri path");
  }
  if (!index) {
    throw Error(std::string(kDeviceVariable) + "=" + choice + ": no such EGL device (" +
                ListText(devices) + ")");
  }
  try {
    return open_device(*index);
  } catch (const Error& e) {
    throw Error(std::string(kDeviceVariable) + "=" + choice + ": device " + std::to_string(*index) +
                " (" + devices[*index].name + "): " + e.what());
  }
}

// Opens libEGL and selects the display once per process.
const EglDisplay& Egl() {
  return LoadOnce([] { return SelectDisplay(OpenEgl()); });
}

class EglContext final : public GlContext {
 public:
  EglContext() : egl_(Egl()) {
    const EglLibrary& egl = egl_.egl;
    BindOpenGl();
    // any config that renders desktop OpenGL: drawing goes to framebuffer objects, never to a
    // surface of the config's format (EGL_SURFACE_TYPE 0 drops the default EGL_WINDOW_BIT)
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                        EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!egl.choose_config(egl_.display, config_attributes, &config, 1, &configs) || configs < 1) {
      throw Error("EGL (" + egl_.label + ") has no config for OpenGL (" +
                  ErrorName(egl.get_error()) + ")");
    }
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                         EGL_CONTEXT_MINOR_VERSION, 3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = egl.create_context(egl_.display, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) {
      throw Error("EGL (" + egl_.label + ") could not create an OpenGL 3.3 core context (" +
                  ErrorName(egl.get_error()) + ")");
    }
    MakeCurrent();
    description_ = DescribeCurrentContext("EGL (" + egl_.label + ")");
  }

  ~EglContext() override {
    const EglLibrary& egl = egl_.egl;
    if (egl.get_current_context() == context_) {
      egl.make_current(egl_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    egl.destroy_context(egl_.display, context_);
  }

  void MakeCurrent() override {
    const EglLibrary& egl = egl_.egl;
    BindOpenGl();  // the bound API is per thread
    if (!egl.make_current(egl_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw Error("EGL (" + egl_.label + ") could not make its OpenGL context current (" +
                  ErrorName(egl.get_error()) + ")");
    }
    if (UseGlFunctionsFrom(egl.get_proc_address)) {
      // the table was another backend's: an OSMesa context may have been made current behind
      // libEGL's back, and libglvnd's eglMakeCurrent returns at once, without asking Mesa, for
      // the context it believes current already; so release this one and bind it again
      egl.make_current(egl_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      egl.make_current(egl_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
    }
  }
  void Release() override {
    egl_.egl.make_current(egl_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  Backend backend() const override { return Backend::kEgl; }
  const std::string& description() const override { return description_; }

 private:
  void BindOpenGl() const {
    if (!egl_.egl.bind_api(EGL_OPENGL_API)) {
      throw Error("EGL (" + egl_.label + ") cannot bind the OpenGL API (" +
                  ErrorName(egl_.egl.get_error()) + ")");
    }
  }

  const EglDisplay& egl_;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string description_;
};

}  // namespace

void LoadEgl() { Egl(); }

std::unique_ptr<GlContext> CreateEglContext() { return std::make_unique<EglContext>(); }

}  // namespace urdfsnap::gl
