// The fuzz build's own copy of stb_image's decoder (Debian's header, the same version as the
// libstb that the library links). libstb is built without coverage or sanitizers, so without
// this copy libFuzzer would see nothing of the PNG decoder and ASan would check none of it;
// the executable's definitions take the place of the shared library's.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
