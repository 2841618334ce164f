// urdfsnap-serve.so's entry point: its table of server.h's functions, for its own build only.
#include <utility>

#include "common/module_loader.h"
#include "serve/loaded_server.h"

namespace {

using urdfsnap::serve::Server;

Server* Create(urdfsnap::serve::ServerOptions options, urdfsnap::Warnings& warnings) {
  return new Server(std::move(options), warnings);
}
void Destroy(Server* server) { delete server; }
int Bind(Server& server) { return server.Bind(); }
void Run(Server& server) { server.Run(); }
bool Stop(Server& server) { return server.Stop(); }

}  // namespace

// kServerModuleEntry
extern "C" __attribute__((visibility("default"))) const void* urdfsnap_serve_module(
    const char* version) {
  static const urdfsnap::serve::ServerModule table{&urdfsnap::serve::IsLoopback, &Create, &Destroy,
                                                   &Bind, &Run, &Stop};
  return urdfsnap::IsOwnVersion(version) ? &table : nullptr;
}
