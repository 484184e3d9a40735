#pragma once
/// @file
/// Delta debugging (Zeller and Hildebrandt, "Simplifying and Isolating Failure-Inducing
/// Input", IEEE TSE 2002): ddmin, by removing complements. Shrinks a failing list of items
/// (faces of a mesh, operations of a sequence) to one where removing any single item makes
/// the failure go away (1-minimal).

#include <algorithm>
#include <vector>

namespace crossdiv::verification {

/// Removes chunks of `items` while `still_fails(candidate)` holds: split into n chunks, try
/// keeping the complement of each; on success continue with n - 1 chunks, otherwise double n,
/// until the chunks are single items. Order is kept. `still_fails` is not called on `items`
/// itself (the caller knows it fails) nor on an empty list.
template <class T, class StillFails>
std::vector<T> ddmin(std::vector<T> items, StillFails&& still_fails) {
    for (size_t n = 2; items.size() >= 2;) {
        bool reduced = false;
        const size_t chunk = (items.size() + n - 1) / n;
        for (size_t start = 0; start < items.size(); start += chunk) {
            std::vector<T> complement(items.begin(), items.begin() + static_cast<long>(start));
            complement.insert(complement.end(), items.begin() + static_cast<long>(std::min(start + chunk, items.size())), items.end());
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
