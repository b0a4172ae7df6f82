#pragma once
// Planning work spread over the machine's cores (the layouts of the walls' sides, each side's
// row candidates and the texture errors are independent and pure).

#include <functional>

namespace cavewall::walls {

// Calls fn(i) for every i in [0, n), on up to std::thread::hardware_concurrency() threads (the
// calling thread is one of them), and returns when all are done. fn must be safe to call
// concurrently for different i; results must go to slots indexed by i, so the outcome does not
// depend on the order. The first exception thrown by fn is rethrown here after every thread
// has stopped. A call made from inside fn (a nested parallelFor) runs serially on its calling
// thread: the outer loop already keeps every core busy, and starting threads per inner call
// would only add overhead.
void parallelFor(int n, const std::function<void(int)>& fn);

}  // namespace cavewall::walls
