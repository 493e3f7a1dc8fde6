#include "viewer/window.h"

#include <cctype>

#include "vk/loader.h"  // Vulkan types before GLFW, so glfwCreateWindowSurface is declared
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace tessera::viewer {
namespace {

std::string lastGlfwError;  // GLFW reports failures through a callback, not return values

void recordGlfwError(int, const char* description) { lastGlfwError = description; }

std::string glfwReason() {
  return lastGlfwError.empty() ? std::string("no reason given") : lastGlfwError;
}

}  // namespace

// W wireframe, C colouring, + and - the tolerance (either row of keys), F freeze, Esc or Q quit.
std::optional<KeyAction> keyActionFor(int glfwKey) {
  switch (glfwKey) {
    case GLFW_KEY_W: return KeyAction::Wireframe;
    case GLFW_KEY_C: return KeyAction::Colour;
    case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: return KeyAction::Coarser;
    case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: return KeyAction::Finer;
    case GLFW_KEY_F: return KeyAction::Freeze;
    case GLFW_KEY_ESCAPE: case GLFW_KEY_Q: return KeyAction::Quit;
    default: return std::nullopt;
  }
}

int glfwKeyNamed(const std::string& name) {
  if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
    return GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(name[0])) - 'A');
  if (name == "=" || name == "+") return GLFW_KEY_EQUAL;  // '+' is shifted '=' on the keyboard
  if (name == "-") return GLFW_KEY_MINUS;
  if (name == "KP+") return GLFW_KEY_KP_ADD;
  if (name == "KP-") return GLFW_KEY_KP_SUBTRACT;
  if (name == "Esc") return GLFW_KEY_ESCAPE;
  return -1;
}

// The input handlers: GLFW's callbacks and the scripted input both call these.
struct Window::State {
  InputEvents pending;
  bool dragging = false;
  bool cursorSeen = false;  // lastX, lastY hold a motion event's position
  double lastX = 0, lastY = 0;

  void key(int glfwKey) {
    if (const std::optional<KeyAction> action = keyActionFor(glfwKey))
      pending.keys.push_back(*action);
  }
  // The press is where the last motion event put the cursor: events come in order, and one
  // poll may hold the press, the whole drag and the release (a slow frame, a quick hand).
  void leftButton(bool pressed) { dragging = pressed; }
  void cursor(double x, double y) {
    if (dragging) {
      pending.dragX += x - lastX;
      pending.dragY += y - lastY;
    }
    lastX = x;
    lastY = y;
    cursorSeen = true;
  }
  void wheel(double steps) { pending.wheel += steps; }
};

Window::Window(int width, int height, const std::string& title) : state_(new State) {
  glfwSetErrorCallback(recordGlfwError);
  if (!glfwInit())
    throw WindowSystemUnavailable("no window system: " + glfwReason() +
                                  " (an X server is needed; `xvfb-run -a tessera view ...` "
                                  "gives a virtual one)");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw WindowSystemUnavailable("no window system: GLFW finds no Vulkan loader with surface "
                                  "support (" + glfwReason() + ")");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw WindowSystemUnavailable("no window system: cannot open a window: " + glfwReason());
  }
  glfwSetWindowUserPointer(window_, state_.get());
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_PRESS || action == GLFW_REPEAT)
      static_cast<State*>(glfwGetWindowUserPointer(w))->key(key);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    auto* s = static_cast<State*>(glfwGetWindowUserPointer(w));
    // No motion event yet: the cursor's position now (after the press, if it has moved since).
    if (!s->cursorSeen) glfwGetCursorPos(w, &s->lastX, &s->lastY);
    s->leftButton(action == GLFW_PRESS);
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    static_cast<State*>(glfwGetWindowUserPointer(w))->cursor(x, y);
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    static_cast<State*>(glfwGetWindowUserPointer(w))->wheel(dy);
  });
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<const char*> Window::requiredInstanceExtensions() const {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names)
    throw WindowSystemUnavailable("no window system: no Vulkan surface extensions (" +
                                  glfwReason() + ")");
  return std::vector<const char*>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkResult result = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
  if (result != VK_SUCCESS)
    throw WindowSystemUnavailable("no window system: glfwCreateWindowSurface failed (VkResult " +
                                  std::to_string(int(result)) + "): " + glfwReason());
  return surface;
}

void Window::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

bool Window::waitWhileMinimised() {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  if (width > 0 && height > 0) return false;
  glfwWaitEvents();
  return true;
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_); }

void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

InputEvents Window::poll() {
  glfwPollEvents();
  InputEvents events = std::move(state_->pending);
  state_->pending = {};
  return events;
}

void Window::injectKey(int glfwKey) { state_->key(glfwKey); }

// Press where the cursor was last seen, move by (dx, dy), release: as a hand would drag.
void Window::injectDrag(double dx, double dy) {
  state_->leftButton(true);
  state_->cursor(state_->lastX + dx, state_->lastY + dy);
  state_->leftButton(false);
}

void Window::injectWheel(double steps) { state_->wheel(steps); }

}  // namespace tessera::viewer
