// The live view's server (server.h) through the serve module, urdfsnap-serve.so
// (common/module_loader.h): the server, cpp-httplib and what that library loads (OpenSSL, brotli)
// are loaded by `urdfsnap serve` alone, when it starts. The module carries its own copy of the
// render core the server uses.
#pragma once

#include <string>

#include "common/warnings.h"
#include "serve/server.h"

namespace urdfsnap::serve {

// the module's entry point (server_module_entry.cpp)
inline constexpr char kServerModuleEntry[] = "urdfsnap_serve_module";

// The module's table: server.h's functions.
struct ServerModule {
  bool (*is_loopback)(const std::string& address);
  Server* (*create)(ServerOptions options, Warnings& warnings);
  void (*destroy)(Server* server);
  int (*bind)(Server& server);
  void (*run)(Server& server);
  bool (*stop)(Server& server);
};

// The module's table, loaded on the first call. Throws urdfsnap::Error "the live view's server
// ...: why" when the module is missing, broken or from another build.
const ServerModule& LoadServerModule();

// A serve::Server made and driven through the module: the same constructor and functions.
class LoadedServer {
 public:
  LoadedServer(ServerOptions options, Warnings& warnings);
  ~LoadedServer();
  LoadedServer(const LoadedServer&) = delete;
  LoadedServer& operator=(const LoadedServer&) = delete;

  int Bind() { return module_.bind(*server_); }
  void Run() { module_.run(*server_); }
  bool Stop() { return module_.stop(*server_); }

 private:
  const ServerModule& module_;
  Server* server_;
};

}  // namespace urdfsnap::serve
