// The library's errors as Python exceptions (python/parashade/errors.py): the class says the category,
// the message is the command line's, exit_code its exit code (docs/cli.md).
#include <new>

#include "bindings.hpp"
#include "parashade/combinations.hpp"
#include "parashade/errors.hpp"

namespace parashade::python {
namespace {

void raise(const char* name, const std::string& message) {
  pybind11::object cls = pybind11::module_::import("parashade.errors").attr(name);
  PyErr_SetObject(cls.ptr(), pybind11::str(message).ptr());
}

}  // namespace

void register_error_translation() {
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ConfigError& e) {
      raise("ConfigError", e.what());
    } catch (const UsageError& e) {
      raise("UsageError", e.what());
    } catch (const InputError& e) {
      raise("InputError", e.what());
    } catch (const DeviceError& e) {
      raise("DeviceError", e.what());
    } catch (const Error& e) {
      raise("Error", e.what());
    } catch (const std::bad_alloc&) {
      raise("InputError", "out of host memory");  // as the command line says it, exit 3
    }
  });
}

}  // namespace parashade::python
