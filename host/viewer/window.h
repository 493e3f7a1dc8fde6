// The viewer's window (GLFW, X11 on Debian) and the mouse and keys it reports. The only file
// that includes GLFW: the library and the rest of the viewer never see it.
#pragma once
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "vk/backend_only.h"
#include <vulkan/vulkan_core.h>

struct GLFWwindow;

namespace tessera::viewer {

// No window system to show a window in: no DISPLAY, glfwInit failing, no Vulkan surface
// support. `tessera view` exits 3 (docs/cli.md) with the message.
class WindowSystemUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The viewer's keys (docs/cli.md, `tessera view`).
enum class KeyAction { Wireframe, Colour, Finer, Coarser, Freeze, Quit };

// The key bindings: the action of GLFW's key code `glfwKey`, none for a key the viewer leaves
// alone. Real key presses and scripted ones (--script) both go through it.
std::optional<KeyAction> keyActionFor(int glfwKey);
// The GLFW key code of a key as a script names it: a letter A..Z (either case), "=" or "+"
// (the same key), "-", "KP+", "KP-", "Esc"; -1 for any other name.
int glfwKeyNamed(const std::string& name);

// What happened since the last poll: key presses, the mouse drag in pixels with the left
// button held, and wheel steps (positive: away from the user, zoom in).
struct InputEvents {
  std::vector<KeyAction> keys;
  double dragX = 0, dragY = 0;
  double wheel = 0;
};

class Window {
 public:
  // Initialises GLFW and opens a window with no client API (Vulkan draws into it). Throws
  // WindowSystemUnavailable with GLFW's own reason when either fails.
  Window(int width, int height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // The instance extensions a surface for this window needs (VK_KHR_surface and the
  // platform's); the names live as long as GLFW.
  std::vector<const char*> requiredInstanceExtensions() const;
  // Throws WindowSystemUnavailable when GLFW cannot make one.
  VkSurfaceKHR createSurface(VkInstance instance) const;

  void framebufferSize(int& width, int& height) const;
  // Minimised (a zero-sized framebuffer): nothing can be drawn; waits for the next event.
  bool waitWhileMinimised();
  bool closeRequested() const;
  void requestClose();
  void setTitle(const std::string& title);
  InputEvents poll();

  // Scripted input (--script): fed through the handlers GLFW's callbacks call, so the next
  // poll() reports it as it would a real key press, a drag with the left button, or the wheel.
  void injectKey(int glfwKey);
  void injectDrag(double dx, double dy);
  void injectWheel(double steps);

 private:
  GLFWwindow* window_ = nullptr;
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace tessera::viewer
