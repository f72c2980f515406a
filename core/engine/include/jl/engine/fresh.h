// Scratch held by pointer, for owners that are copied (an event's trial
// copies the world, the ladder; a keyframe the stepper): a copy starts with
// an empty T of its own, an assignment keeps the owner's T and so the
// capacity of its buffers. Nothing in scratch is worth copying (each use
// fills it afresh), and a copy that shared it would share it between the
// threads that run simulations. By pointer, so that T may stay private to
// its part: the members are instantiated where T is defined (`template
// class Fresh<T>;` there, `extern template class Fresh<T>;` beside the owner).
#pragma once

#include <memory>

namespace jl {

template <class T>
class Fresh {
public:
    Fresh();
    ~Fresh();
    Fresh(const Fresh&);
    Fresh& operator=(const Fresh&) { return *this; }
    T& operator*() const { return *object_; }
    T* operator->() const { return object_.get(); }

private:
    std::unique_ptr<T> object_;
};

template <class T>
Fresh<T>::Fresh() : object_(std::make_unique<T>()) {}
template <class T>
Fresh<T>::~Fresh() = default;
template <class T>
Fresh<T>::Fresh(const Fresh&) : Fresh() {}

// The engine's own, instantiated in scratch.cpp.
class PinSolver;
struct Scratch;
extern template class Fresh<PinSolver>;
extern template class Fresh<Scratch>;

}  // namespace jl
