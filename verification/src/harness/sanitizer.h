#pragma once
// CROSSDIV_ADDRESS_SANITIZER: defined when this translation unit is built with the address
// sanitizer (GCC's or Clang's spelling), whose shadow memory rules out memory limits.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CROSSDIV_ADDRESS_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) && !defined(CROSSDIV_ADDRESS_SANITIZER)
#define CROSSDIV_ADDRESS_SANITIZER 1
#endif
