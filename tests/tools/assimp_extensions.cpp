// Prints the file extensions the linked assimp imports, one a line, lower case and without the
// dot: the tool sweep over assimp's test models picks its files by this list, so it follows
// whatever assimp version the tools are built against.
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <sstream>
#include <string>

int main() {
    std::string list;
    Assimp::Importer().GetExtensionList(list);  // "*.3ds;*.obj;..."
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ';');) {
        const auto dot = item.find('.');
        if (dot == std::string::npos) continue;
        std::string ext = item.substr(dot + 1);
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
        std::cout << ext << "\n";
    }
}
