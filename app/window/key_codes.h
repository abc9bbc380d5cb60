// GLFW's key names as the browser's key codes, which Shadertoy's keyboard
// texture is indexed by (65 is A, 37 to 40 the arrows).
#pragma once

namespace rm {

// The browser key code of a GLFW key, or -1 for a key the browser does not name.
int browser_key_code(int glfw_key);

}  // namespace rm
