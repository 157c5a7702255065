#pragma once
// A vector whose resize() default-initialises the new elements: for a trivial type it leaves
// them unwritten. The mesh sweep's large arrays (tens of megabytes at 10^5 faces) are each
// written in full right after they are sized, so zeroing them first would be one more pass
// over all of their memory.
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace ccd::cloth {

template <class T, class A = std::allocator<T>>
class DefaultInitAllocator : public A {
  using Traits = std::allocator_traits<A>;

 public:
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };
  using A::A;
  DefaultInitAllocator() = default;
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<A&>(*this), p, std::forward<Args>(args)...);
  }
};

template <class T>
using DefaultInitVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace ccd::cloth
