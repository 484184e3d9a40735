#pragma once
/// @file
/// Delta debugging (Zeller and Hildebrandt, "Simplifying and Isolating Failure-Inducing
/// Input", IEEE TSE 2002): ddmin, by removing complements. Shrinks a failing list of items
/// (faces of a mesh, operations of a sequence) to one where removing any single item makes
/// the failure go away (1-minimal).

#include <algorithm>
#include <vector>

namespace crossdiv::verification {

/// What each round of ddmin tries.
enum class DdminSteps {
    /// The complement of each chunk: removes at most one chunk a round, so a failure that needs
    /// most of the items keeps them with few tests.
    Complements,
    /// Each chunk alone first, then each complement (Zeller and Hildebrandt's ddmin in full): a
    /// failure that a small part of a large input shows is reached in halvings, and a failure
    /// that depends on every item's presence (a random stream drawn per item) still ends small.
    SubsetsThenComplements,
};

/// Removes chunks of `items` while `still_fails(candidate)` holds: split into n chunks, try
/// (with SubsetsThenComplements) keeping one chunk alone, then keeping the complement of each;
/// on a chunk kept alone continue with 2 chunks, on a complement with n - 1, otherwise double n,
/// until the chunks are single items. Order is kept. `still_fails` is not called on `items`
/// itself (the caller knows it fails) nor on an empty list.
template <class T, class StillFails>
std::vector<T> ddmin(std::vector<T> items, StillFails&& still_fails, DdminSteps steps = DdminSteps::Complements) {
    for (size_t n = 2; items.size() >= 2;) {
        bool reduced = false;
        const size_t chunk = (items.size() + n - 1) / n;
        if (steps == DdminSteps::SubsetsThenComplements)
            for (size_t start = 0; start < items.size(); start += chunk) {
                std::vector<T> subset(items.begin() + static_cast<long>(start),
                                      items.begin() + static_cast<long>(std::min(start + chunk, items.size())));
                if (still_fails(subset)) {
                    items = std::move(subset);
                    n = 2;
                    reduced = true;
                    break;
                }
            }
        if (reduced) continue;
        // With two chunks each complement is the other chunk, tried above.
        if (steps == DdminSteps::Complements || n > 2)
            for (size_t start = 0; start < items.size(); start += chunk) {
                std::vector<T> complement(items.begin(), items.begin() + static_cast<long>(start));
                complement.insert(complement.end(), items.begin() + static_cast<long>(std::min(start + chunk, items.size())),
                                  items.end());
                if (still_fails(complement)) {
                    items = std::move(complement);
                    n = std::max<size_t>(n - 1, 2);
                    reduced = true;
                    break;
                }
            }
        if (reduced) continue;
        if (n >= items.size()) break;
        n = std::min(items.size(), 2 * n);
    }
    return items;
}

}  // namespace crossdiv::verification
