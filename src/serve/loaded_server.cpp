// LoadServerModule and LoadedServer: LoadModule of urdfsnap-serve.so and calls through its table.
#include "serve/loaded_server.h"

#include <utility>

#include "common/module_loader.h"

namespace urdfsnap::serve {

const ServerModule& LoadServerModule() {
  return LoadModule<ServerModule>(URDFSNAP_SERVE_MODULE, kServerModuleEntry,
                                  "the live view's server (cpp-httplib)");
}

LoadedServer::LoadedServer(ServerOptions options, Warnings& warnings)
    : module_(LoadServerModule()), server_(module_.create(std::move(options), warnings)) {}

LoadedServer::~LoadedServer() { module_.destroy(server_); }

}  // namespace urdfsnap::serve
