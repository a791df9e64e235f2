package io.concord.jade;

import io.concord.layers.platform.Gateway;
import io.concord.layers.GatewayProvider;


/** Provides the HTTP MTP to {@code Boot -http}, by {@link java.util.ServiceLoader}. */
public final class HttpMtpProvider implements GatewayProvider {

    @Override
    public String kind() {
        return "http";
    }

    @Override
    public Gateway create(String host, int port) {
        return new HttpMtp(host, port);
    }

    @Override
    public Gateway create(String host, int port, java.util.Map<String, String> settings) {
        return new HttpMtp(host, port).trust(new HttpMtp.Trust(list(settings.get("http-platforms")),
                list(settings.get("http-hosts"))));
    }

    private static java.util.Set<String> list(String commaSeparated) {
        return commaSeparated == null ? java.util.Set.of() : new java.util.HashSet<>(java.util.List.of(commaSeparated.split(",")));
    }
}
