#include "meshes/msh_text_check.h"

#include "common/input_error.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_set>
#include <vector>

namespace chipflex::meshes
{
namespace
{
bool is_integer(const std::string& token)
{
  return !token.empty() && token.find_first_not_of("+-0123456789") == std::string::npos;
}

bool is_number(const std::string& token)
{
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return !token.empty() && *end == '\0';
}

/// The number of nodes of a gmsh element type that chipflex reads, or 0 for any other:
/// points, lines, triangles, quadrilaterals, tetrahedra and hexahedra of order 1 and 2
/// (gmsh's MSH element types 15, 1, 8, 2, 9, 3, 10, 16, 4, 11, 5, 12 and 17). A table, not
/// gmsh::model::mesh::getElementProperties: libgmsh 4.8 frees a prism's basis with the
/// wrong delete there (AddressSanitizer, found by fuzzing), and the mesh readers refuse
/// prisms, pyramids and higher orders anyway.
int nodes_of_type(long type)
{
  struct TypeNodes
  {
    long type;
    int nodes;
  };
  static constexpr TypeNodes table[] = {
      {15, 1},  // point
      {1, 2},   // line
      {8, 3},   // quadratic line
      {2, 3},   // triangle
      {9, 6},   // quadratic triangle
      {3, 4},   // quadrilateral
      {10, 9},  // quadratic quadrilateral (9 nodes)
      {16, 8},  // quadratic quadrilateral (8 nodes)
      {4, 4},   // tetrahedron
      {11, 10}, // quadratic tetrahedron
      {5, 8},   // hexahedron
      {12, 27}, // quadratic hexahedron (27 nodes)
      {17, 20}, // quadratic hexahedron (20 nodes)
  };
  for (const auto& entry : table)
    if (entry.type == type)
      return entry.nodes;
  return 0;
}

/// Reads the file line by line and refuses, with the file and line, what gmsh would misread.
class MshTextChecker
{
public:
  explicit MshTextChecker(const std::string& path) : path_(path) {}

  void check()
  {
    read_lines();
    expect_line("$MeshFormat");
    check_format();
    expect_line("$EndMeshFormat");
    std::set<std::string> seen;
    while (next())
    {
      if (line_.empty())
        continue;
      const std::string section = line_;
      if (!seen.insert(section).second)
        refuse("a second " + section + " section");
      if (section == "$PhysicalNames")
        physical_names();
      else if (section == "$Entities" && version_ == 4.1)
        entities();
      else if (section == "$Nodes")
        version_ == 4.1 ? nodes_41() : nodes_2();
      else if (section == "$Elements")
        version_ == 4.1 ? elements_41() : elements_2();
      else
        refuse("'" + line_.substr(0, 40) +
               "' is not a section chipflex reads (a mesh has $PhysicalNames, " +
               (version_ == 4.1 ? "$Entities, " : "") + "$Nodes and $Elements)");
      expect_line("$End" + section.substr(1));
    }
  }

private:
  void read_lines()
  {
    std::ifstream in(path_, std::ios::binary);
    if (!in)
      throw InputError(path_, "cannot open mesh file");
    // A file is its size's worth of entities at most: no sound count or tag exceeds this.
    in.seekg(0, std::ios::end);
    limit_ = 16 * double(in.tellg()) + 1024;
    in.seekg(0);
    for (std::string line; std::getline(in, line); lines_.push_back(line))
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
        line.pop_back();
  }

  bool next()
  {
    if (std::size_t(number_) >= lines_.size())
      return false;
    line_ = lines_[std::size_t(number_)];
    ++number_;
    for (const unsigned char c : line_)
      if (c < 0x20 && c != '\t')
        refuse("not a text mesh file (a control character in the line)");
    tokens_.clear();
    std::istringstream in(line_);
    for (std::string token; in >> token;)
      tokens_.push_back(token);
    for (const auto& token : tokens_)
      // Below 100000, gmsh's arrays for that many tags take under a megabyte; a 9-digit
      // tag alone made it allocate gigabytes. Integer coordinates are the only other
      // integers and rarely reach this.
      if (is_integer(token) && token.size() >= 6 &&
          std::abs(std::strtod(token.c_str(), nullptr)) > limit_)
        refuse("the count or tag " + token + " is larger than a file of this size can hold " +
               "(a damaged mesh file)");
    return true;
  }

  void expect_line(const std::string& expected)
  {
    if (!next() || line_ != expected)
      refuse(expected == "$MeshFormat"
                 ? "not a gmsh mesh: the file does not start with $MeshFormat"
                 : "expected " + expected +
                       (number_ > long(lines_.size()) ? " before the end"
                                                      : ", found '" + line_.substr(0, 40) + "'"));
  }

  /// The next line, which must hold `n` integers (n = 0: any number of them, at least one).
  void integer_line(std::size_t n, const std::string& what)
  {
    if (!next() || (n > 0 && tokens_.size() != n) || tokens_.empty())
      refuse("expected " + what);
    for (const auto& token : tokens_)
      if (!is_integer(token))
        refuse("expected " + what + ", found '" + token + "'");
  }

  long integer(std::size_t k) const { return std::strtol(tokens_[k].c_str(), nullptr, 10); }

  /// A count that the lines left in the file can hold.
  long count(std::size_t k, const std::string& what)
  {
    const long n = integer(k);
    if (n < 0 || n > long(lines_.size()))
      refuse(what + " " + tokens_[k] + " is not a count this file can hold");
    return n;
  }

  void check_format()
  {
    if (!next() || tokens_.size() != 3)
      refuse("expected the format line 'version file-type data-size'");
    version_ = std::strtod(tokens_[0].c_str(), nullptr);
    if (tokens_[1] != "0")
      refuse("a binary .msh file (or file type '" + tokens_[1] +
             "'): chipflex reads text meshes; save it as text (gmsh option Mesh.Binary = 0)");
    if (version_ != 4.1 && (version_ < 2.0 || version_ > 2.2))
      refuse("mesh format " + tokens_[0] + " is not read (formats 4.1 and 2.2 are)");
  }

  void physical_names()
  {
    integer_line(1, "the number of physical names");
    for (long k = count(0, "the number of physical names"); k > 0; --k)
    {
      // gmsh 4.8 crashes on a physical-name line without its quoted name.
      if (!next())
        refuse("expected a physical name before the end");
      std::istringstream f(line_);
      int dim = -1;
      long tag = 0;
      std::string rest;
      f >> dim >> tag;
      std::getline(f >> std::ws, rest);
      if (!f || dim < 0 || dim > 3 || rest.size() < 2 || rest.front() != '"' ||
          rest.find('"', 1) == std::string::npos)
        refuse("not a physical name (dim tag \"name\"): '" + line_ + "'");
    }
  }

  /// A point is `tag x y z nPhysicals physicals...`; a curve, surface or volume `tag minX
  /// minY minZ maxX maxY maxZ nPhysicals physicals... nBounding bounding...`. gmsh sizes its
  /// vectors by the counts, so a count that falls on a coordinate allocates gigabytes.
  bool is_entity_line(bool point) const
  {
    std::size_t at = point ? 4 : 7;
    if (tokens_.size() <= at || !is_integer(tokens_[0]))
      return false;
    for (std::size_t k = 1; k < at; ++k)
      if (!is_number(tokens_[k]))
        return false;
    for (int list = 0; list < (point ? 1 : 2); ++list)
    {
      if (at >= tokens_.size() || !is_integer(tokens_[at]))
        return false;
      const long n = integer(at);
      if (n < 0 || n > long(tokens_.size() - at - 1))
        return false;
      for (long k = 1; k <= n; ++k)
        if (!is_integer(tokens_[at + std::size_t(k)]))
          return false;
      at += 1 + std::size_t(n);
    }
    return at == tokens_.size();
  }

  void entities()
  {
    integer_line(4, "the entity counts (nPoints nCurves nSurfaces nVolumes)");
    long counts[4];
    for (int d = 0; d < 4; ++d)
      counts[d] = count(std::size_t(d), "the number of entities");
    for (int d = 0; d < 4; ++d)
      for (long k = counts[d]; k > 0; --k)
        if (!next() || !is_entity_line(d == 0))
          refuse(std::string("not a ") + (d == 0 ? "point" : "curve, surface or volume") +
                 " entity, or its counts do not match its tags");
  }

  /// An MSH 4.1 `$Nodes` or `$Elements` section: `nBlocks nItems minTag maxTag`, then the
  /// blocks, each read by `block`, which returns how many items it held.
  template <typename Block>
  void blocks_41(const std::string& item, Block block)
  {
    integer_line(4, "the " + item + " counts (blocks, " + item + "s, smallest and largest tag)");
    const long blocks = count(0, "the number of " + item + " blocks");
    const long total = count(1, "the number of " + item + "s");
    long seen = 0;
    for (long b = 0; b < blocks; ++b)
      seen += block();
    if (seen != total)
      refuse("the " + item + " blocks hold " + std::to_string(seen) + " " + item +
             "s, the header says " + std::to_string(total));
  }

  void nodes_41()
  {
    blocks_41("node",
              [this]
              {
                integer_line(4, "a node block's header (entityDim entityTag parametric nNodes)");
                const long dim = integer(0), parametric = integer(2);
                const long n = count(3, "the number of nodes in a block");
                if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1)
                  refuse("a node block's dimension or parametric flag is out of range");
                for (long k = 0; k < n; ++k)
                {
                  integer_line(1, "a node tag");
                  declare_node(0);
                }
                const std::size_t n_coordinates = 3 + std::size_t(parametric * dim);
                for (long k = 0; k < n; ++k)
                {
                  if (!next() || tokens_.size() != n_coordinates)
                    refuse("expected a node's " + std::to_string(n_coordinates) + " coordinates");
                  for (const auto& token : tokens_)
                    if (!is_number(token))
                      refuse("not a coordinate: '" + token + "'");
                }
                return n;
              });
  }

  void nodes_2()
  {
    integer_line(1, "the number of nodes");
    for (long k = count(0, "the number of nodes"); k > 0; --k)
      if (!next() || tokens_.size() != 4 || !is_integer(tokens_[0]) || !is_number(tokens_[1]) ||
          !is_number(tokens_[2]) || !is_number(tokens_[3]))
        refuse("expected a node 'tag x y z'");
      else
        declare_node(0);
  }

  /// An element line of `n_nodes` node tags after `leading` integers.
  void element_line(long type, std::size_t leading)
  {
    const int n_nodes = nodes_of_type(type);
    if (n_nodes == 0)
      refuse("element type " + std::to_string(type) +
             " is not one chipflex reads (points, lines, triangles, quadrilaterals, "
             "tetrahedra, hexahedra; linear or quadratic)");
    if (tokens_.size() != leading + std::size_t(n_nodes))
      refuse("an element of type " + std::to_string(type) + " needs " + std::to_string(n_nodes) +
             " nodes");
    // gmsh keeps a null node for a tag it has not read, and crashes on it later.
    for (std::size_t k = leading; k < tokens_.size(); ++k)
      if (!node_tags_.count(integer(k)))
        refuse("the element's node " + tokens_[k] + " is not among the mesh's nodes");
  }

  void elements_41()
  {
    blocks_41("element",
              [this]
              {
                integer_line(4, "an element block's header (entityDim entityTag type nElements)");
                const long type = integer(2);
                const long n = count(3, "the number of elements in a block");
                for (long k = 0; k < n; ++k)
                {
                  integer_line(0, "an element (tag nodes...)");
                  element_line(type, 1);
                }
                return n;
              });
  }

  void elements_2()
  {
    integer_line(1, "the number of elements");
    for (long k = count(0, "the number of elements"); k > 0; --k)
    {
      integer_line(0, "an element (tag type nTags tags... nodes...)");
      if (tokens_.size() < 3 || integer(2) < 0 || integer(2) > long(tokens_.size()) - 3)
        refuse("an element's number of tags does not fit its line");
      element_line(integer(1), 3 + std::size_t(integer(2)));
    }
  }

  /// Records the node tag in token k: a positive integer, each tag once.
  void declare_node(std::size_t k)
  {
    const long tag = integer(k);
    if (tag <= 0 || !node_tags_.insert(tag).second)
      refuse("node tag " + tokens_[k] + (tag <= 0 ? " is not positive" : " appears twice"));
  }

  [[noreturn]] void refuse(const std::string& problem) const
  {
    throw InputError(path_ + ":" + std::to_string(number_), problem);
  }

  std::string path_;
  std::vector<std::string> lines_;
  double limit_ = 0;
  long number_ = 0; ///< lines read so far: the current line's number
  std::string line_;
  std::vector<std::string> tokens_;
  double version_ = 0;
  std::unordered_set<long> node_tags_;
};
} // namespace

void check_msh_text(const std::string& path)
{
  MshTextChecker(path).check();
}
} // namespace chipflex::meshes
