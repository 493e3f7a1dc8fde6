#include "viewer/window.h"

#include "vk/loader.h"  // Vulkan types before GLFW, so glfwCreateWindowSurface is declared
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace tessera::viewer {
namespace {

std::string lastGlfwError;  // GLFW reports failures through a callback, not return values

void recordGlfwError(int, const char* description) { lastGlfwError = description; }

// W wireframe, C colouring, + and - the tolerance (either row of keys), F freeze, Esc or Q quit.
bool keyAction(int key, KeyAction& action) {
  switch (key) {
    case GLFW_KEY_W: action = KeyAction::Wireframe; return true;
    case GLFW_KEY_C: action = KeyAction::Colour; return true;
    case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: action = KeyAction::Coarser; return true;
    case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: action = KeyAction::Finer; return true;
    case GLFW_KEY_F: action = KeyAction::Freeze; return true;
    case GLFW_KEY_ESCAPE: case GLFW_KEY_Q: action = KeyAction::Quit; return true;
    default: return false;
  }
}

std::string glfwReason() {
  return lastGlfwError.empty() ? std::string("no reason given") : lastGlfwError;
}

}  // namespace

struct Window::State {
  InputEvents pending;
  bool dragging = false;
  double lastX = 0, lastY = 0;
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
    KeyAction viewerAction;
    if ((action == GLFW_PRESS || action == GLFW_REPEAT) && keyAction(key, viewerAction))
      static_cast<State*>(glfwGetWindowUserPointer(w))->pending.keys.push_back(viewerAction);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    auto* s = static_cast<State*>(glfwGetWindowUserPointer(w));
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    s->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(w, &s->lastX, &s->lastY);
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    auto* s = static_cast<State*>(glfwGetWindowUserPointer(w));
    if (s->dragging) {
      s->pending.dragX += x - s->lastX;
      s->pending.dragY += y - s->lastY;
    }
    s->lastX = x;
    s->lastY = y;
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    static_cast<State*>(glfwGetWindowUserPointer(w))->pending.wheel += dy;
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

}  // namespace tessera::viewer
