#pragma once
// Errors found while a scene's model is built (the vehicle model, its contact geometry source,
// track, tables), located at the key of the scene or vehicle file behind them, so that `validate`
// and `run` report them as they report the loader's own errors: file, line, column, key.
// Private to the scenarios library.

#include <exception>

namespace ferro::scenarios {

struct Scene;

namespace detail {

/// Rethrows `error` (caught while building `scene`'s model): a YamlInputError as it is; a
/// std::invalid_argument as a YamlInputError at the key that set the value it names (or, when
/// none can be told, at the scene's `model` key); anything else as it is.
[[noreturn]] void rethrow_located(const Scene& scene, const std::exception_ptr& error);

}  // namespace detail
}  // namespace ferro::scenarios
