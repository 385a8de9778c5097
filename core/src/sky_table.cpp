// Placeholder while the implementation is being written.
namespace aerial {}
