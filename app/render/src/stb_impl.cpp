// Browser build only: stb's PNG writer and reader (the native build links Debian's libstb, which has them).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
