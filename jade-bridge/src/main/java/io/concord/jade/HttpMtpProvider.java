package io.concord.jade;

import io.concord.layers.platform.Gateway;
import io.concord.layers.platform.GatewayProvider;

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
}
