// Notes on standard error (notes.hpp).
#include "parashade/notes.hpp"

#include <iostream>

namespace parashade {

void print_note(const std::string& text) { std::cerr << "parashade: note: " << text << "\n"; }

}  // namespace parashade
