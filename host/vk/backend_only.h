// Included first by every host/vk/ header. The Vulkan layer belongs to the tessera_vulkan target
// and its users (the CLI, tests, bench), which get TESSERA_VULKAN_BACKEND from it; core code
// (host/<stage>/ without the _vulkan suffix) must not see Vulkan (docs/architecture.md).
#pragma once
#ifndef TESSERA_VULKAN_BACKEND
#error "host/vk/ is the Vulkan backend's: core code may not include it (docs/architecture.md)"
#endif
