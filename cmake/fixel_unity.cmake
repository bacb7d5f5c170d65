# cmake/fixel_unity.cmake - find the Unity test framework for tests/.
#
# fxl_resolve_unity() creates the INTERFACE target fixel_unity that every test
# links, and sets FXL_UNITY_PROVIDER (system | source-dir | download | compat)
# in the caller's scope. Sources are tried in this order, and the choice is
# printed as a banner at configure time:
#
#   1. -DFETCHCONTENT_SOURCE_DIR_UNITY=<unity checkout>  (FetchContent, no
#      network), else an installed Unity: find_package(unity CONFIG), target
#      unity::framework. An installed Unity must have been built with
#      UNITY_INCLUDE_DOUBLE (the tests use TEST_ASSERT_DOUBLE_*); it is
#      skipped with a warning when a probe program does not link.
#   2. Download of the pinned release FXL_UNITY_URL (v2.6.1), verified against
#      FXL_UNITY_SHA256, with a 20 s limit. Skipped when FXL_UNITY_DOWNLOAD is
#      OFF, FXL_UNITY_SHA256 is empty, FETCHCONTENT_FULLY_DISCONNECTED is ON,
#      or the environment sets FXL_OFFLINE. A failed attempt leaves a marker
#      file in the build tree so later reconfigures do not wait again.
#   3. tests/unity_compat: our own small Unity-compatible runner.
#
# FXL_UNITY_COMPAT=ON skips 1 and 2. Whatever is chosen, the tests see
# UNITY_INCLUDE_DOUBLE (double asserts on) and UNITY_USE_FLUSH_STDOUT (each
# result line reaches the log even if a sanitizer kills the test later; for
# an installed Unity only if its library was built with it: the flush is in
# unity.c). An installed Unity must be 2.6.x, the release the tests are
# written against (a later unity.c prints "FAIL." where 2.6 prints "FAIL:").

include_guard(GLOBAL)

option(FXL_UNITY_DOWNLOAD "Download the pinned Unity release when none is installed" ON)
option(FXL_UNITY_COMPAT "Always use tests/unity_compat instead of Unity" OFF)
set(FXL_UNITY_URL
    "https://github.com/ThrowTheSwitch/Unity/archive/refs/tags/v2.6.1.tar.gz"
    CACHE STRING "Unity release archive to download")
# SHA-256 of the GitHub tag archive of Unity v2.6.1. It could not be computed
# here (no network); it is the value several independent public projects pin
# for exactly this URL. If GitHub ever serves different bytes, the download is
# rejected and the build falls back to tests/unity_compat; set this to the
# new hash only after checking the archive. Empty disables the download.
set(FXL_UNITY_SHA256
    "b41a66d45a6b99758fb3202ace6178177014d52fc524bf1f72687d93e9867292"
    CACHE STRING "SHA-256 of FXL_UNITY_URL (empty: never download)")

set(_fxl_unity_compat_dir "${CMAKE_CURRENT_LIST_DIR}/../tests/unity_compat")
get_filename_component(_fxl_unity_compat_dir "${_fxl_unity_compat_dir}" ABSOLUTE)

function(_fxl_unity_banner provider detail)
  message(NOTICE
    "\n"
    "######################################################################\n"
    "##  fixel tests use Unity from: ${provider}\n"
    "##  ${detail}\n"
    "######################################################################\n")
endfunction()

# The FetchContent route shares one tail: the 'unity' target comes from
# Unity's own CMakeLists.txt; give its sources and the tests the same options.
macro(_fxl_unity_from_fetchcontent)
  include(FetchContent)
  FetchContent_MakeAvailable(unity)
  if(NOT TARGET unity)
    message(FATAL_ERROR "fixel: Unity at ${unity_SOURCE_DIR} did not define target 'unity'")
  endif()
  target_compile_definitions(unity PUBLIC UNITY_INCLUDE_DOUBLE UNITY_SUPPORT_64 UNITY_USE_FLUSH_STDOUT)
  target_link_libraries(fixel_unity INTERFACE unity)
endmacro()

# Download FXL_UNITY_URL into the build tree and check its hash.
# Sets <out_var> to the archive path, or to "" when that did not work.
function(_fxl_unity_download out_var)
  set(${out_var} "" PARENT_SCOPE)
  set(dir "${CMAKE_BINARY_DIR}/_deps")
  set(archive "${dir}/unity-download.tar.gz")
  string(TOLOWER "${FXL_UNITY_SHA256}" want)
  # The marker names the URL and hash it was for: changing either retries.
  string(MD5 key "${FXL_UNITY_URL} ${want}")
  set(marker "${dir}/unity-download-${key}.failed")

  # Reuse an earlier download of the same URL with the right hash.
  if(EXISTS "${archive}" AND EXISTS "${archive}.url")
    file(READ "${archive}.url" from)
    file(SHA256 "${archive}" have)
    if(have STREQUAL want AND from STREQUAL FXL_UNITY_URL)
      set(${out_var} "${archive}" PARENT_SCOPE)
      return()
    endif()
  endif()
  file(REMOVE "${archive}" "${archive}.url")
  if(EXISTS "${marker}")
    file(READ "${marker}" why)
    message(STATUS "fixel: not downloading Unity again: ${why}"
                   " (delete ${marker} to retry)")
    return()
  endif()

  message(STATUS "fixel: downloading ${FXL_UNITY_URL} (20 s limit)")
  file(MAKE_DIRECTORY "${dir}")
  file(DOWNLOAD "${FXL_UNITY_URL}" "${archive}.part"
       TIMEOUT 20 INACTIVITY_TIMEOUT 10 TLS_VERIFY ON STATUS status)
  list(GET status 0 code)
  list(GET status 1 text)
  if(NOT code EQUAL 0)
    set(why "download failed: ${text} (${code})")
  else()
    # Checked here rather than with EXPECTED_HASH, which would stop the
    # configure instead of falling back.
    file(SHA256 "${archive}.part" have)
    if(have STREQUAL want)
      file(RENAME "${archive}.part" "${archive}")
      file(WRITE "${archive}.url" "${FXL_UNITY_URL}")
      set(${out_var} "${archive}" PARENT_SCOPE)
      return()
    endif()
    set(why "SHA-256 mismatch: got ${have}, FXL_UNITY_SHA256 is ${want}")
  endif()
  file(REMOVE "${archive}.part")
  file(WRITE "${marker}" "${why}")
  message(STATUS "fixel: ${why}")
endfunction()

# Probe an installed Unity: header found, library links, double and 64-bit
# asserts there. Run where we can: a library built without UNITY_SUPPORT_64
# on a 32-bit host links but takes 32-bit arguments, and its 64-bit assert
# fails (or its double one, without UNITY_INCLUDE_DOUBLE).
function(_fxl_unity_installed_usable out_var)
  include(CheckCSourceCompiles)
  include(CheckCSourceRuns)
  include(CMakePushCheckState)
  cmake_push_check_state(RESET)
  set(CMAKE_REQUIRED_LIBRARIES unity::framework)
  set(CMAKE_REQUIRED_DEFINITIONS -DUNITY_INCLUDE_DOUBLE -DUNITY_SUPPORT_64)
  set(CMAKE_REQUIRED_QUIET ON)
  # Probed at every configure: a cached FALSE from an earlier, unusable
  # Unity would otherwise outlive the rebuild the warning asks for.
  unset(FXL_INSTALLED_UNITY_USABLE CACHE)
  set(_probe [[
#include "unity.h"
void setUp(void) {}
void tearDown(void) {}
static void t(void)
{
    TEST_ASSERT_DOUBLE_WITHIN(0.5, 1.0, 1.25);
    TEST_ASSERT_EQUAL_INT64(0x100000001LL, 0x100000001LL);
    TEST_ASSERT_TRUE(1);
}
int main(void) { UNITY_BEGIN(); RUN_TEST(t); return UNITY_END(); }
]])
  if(CMAKE_CROSSCOMPILING)
    check_c_source_compiles("${_probe}" FXL_INSTALLED_UNITY_USABLE)
  else()
    check_c_source_runs("${_probe}" FXL_INSTALLED_UNITY_USABLE)
  endif()
  cmake_pop_check_state()
  set(${out_var} ${FXL_INSTALLED_UNITY_USABLE} PARENT_SCOPE)
endfunction()

function(_fxl_unity_compat_target)
  if(TARGET fixel_unity_compat)
    return()
  endif()
  add_library(fixel_unity_compat STATIC "${_fxl_unity_compat_dir}/unity.c")
  target_include_directories(fixel_unity_compat PUBLIC "${_fxl_unity_compat_dir}")
  fxl_target_warnings(fixel_unity_compat)
endfunction()

function(fxl_resolve_unity)
  if(TARGET fixel_unity)
    return()
  endif()
  add_library(fixel_unity INTERFACE)
  target_compile_definitions(fixel_unity INTERFACE UNITY_INCLUDE_DOUBLE UNITY_SUPPORT_64 UNITY_USE_FLUSH_STDOUT)
  set(provider "")

  if(FXL_UNITY_COMPAT)
    set(why "FXL_UNITY_COMPAT=ON")
  else()
    set(why "")
    # 1a. A Unity source tree named on the command line.
    if(FETCHCONTENT_SOURCE_DIR_UNITY)
      if(EXISTS "${FETCHCONTENT_SOURCE_DIR_UNITY}/src/unity.h")
        include(FetchContent)
        FetchContent_Declare(unity URL "${FXL_UNITY_URL}")
        _fxl_unity_from_fetchcontent()
        set(provider "source-dir")
        set(detail "FETCHCONTENT_SOURCE_DIR_UNITY=${FETCHCONTENT_SOURCE_DIR_UNITY}")
      else()
        message(FATAL_ERROR "fixel: FETCHCONTENT_SOURCE_DIR_UNITY=${FETCHCONTENT_SOURCE_DIR_UNITY}"
                        " has no src/unity.h (expected a checkout of ThrowTheSwitch/Unity v2.6.1);"
                        " fix the path or drop the option")
      endif()
    endif()

    # 1b. An installed Unity.
    if(NOT provider)
      find_package(unity CONFIG QUIET)
      if(TARGET unity::framework AND
         (NOT unity_VERSION OR unity_VERSION VERSION_LESS 2.6 OR NOT unity_VERSION VERSION_LESS 2.7))
        message(WARNING "fixel: the installed Unity (${unity_DIR}) is version "
                        "'${unity_VERSION}'; the tests are written against 2.6.x. Not using it.")
        string(APPEND why "installed Unity ${unity_VERSION} is not 2.6.x; ")
      elseif(TARGET unity::framework)
        _fxl_unity_installed_usable(ok)
        if(ok)
          target_link_libraries(fixel_unity INTERFACE unity::framework)
          set(provider "system")
          set(detail "find_package(unity) ${unity_VERSION} at ${unity_DIR}")
        else()
          message(WARNING "fixel: the installed Unity (${unity_DIR}) does not link a "
                          "TEST_ASSERT_DOUBLE_WITHIN probe; rebuild it with "
                          "-DUNITY_INCLUDE_DOUBLE. Not using it.")
          string(APPEND why "installed Unity unusable; ")
        endif()
      else()
        string(APPEND why "no installed Unity; ")
      endif()
    endif()

    # 2. The pinned release.
    if(NOT provider)
      if(NOT FXL_UNITY_DOWNLOAD)
        string(APPEND why "FXL_UNITY_DOWNLOAD=OFF")
      elseif(NOT FXL_UNITY_SHA256)
        string(APPEND why "FXL_UNITY_SHA256 is empty")
      elseif(FETCHCONTENT_FULLY_DISCONNECTED)
        string(APPEND why "FETCHCONTENT_FULLY_DISCONNECTED=ON")
      elseif(DEFINED ENV{FXL_OFFLINE})
        string(APPEND why "FXL_OFFLINE is set")
      else()
        _fxl_unity_download(archive)
        if(archive)
          include(FetchContent)
          FetchContent_Declare(unity URL "${archive}" URL_HASH "SHA256=${FXL_UNITY_SHA256}")
          _fxl_unity_from_fetchcontent()
          set(provider "download")
          set(detail "${FXL_UNITY_URL} (SHA-256 verified)")
        else()
          string(APPEND why "download of ${FXL_UNITY_URL} failed")
        endif()
      endif()
    endif()
  endif()

  # 3. Our own runner.
  if(NOT provider)
    _fxl_unity_compat_target()
    target_link_libraries(fixel_unity INTERFACE fixel_unity_compat)
    set(provider "compat")
    set(detail "tests/unity_compat (${why})")
  endif()

  _fxl_unity_banner("${provider}" "${detail}")
  set(FXL_UNITY_PROVIDER "${provider}" PARENT_SCOPE)
endfunction()
