package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.layers.Boot;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.Platform;
import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** {@code Boot -http} finds the HTTP MTP by ServiceLoader when this jar is on the class path, and its container serves it. */
class BootHttpTest {

    @Test
    void bootWithHttpServesTheAccOnceItsContainerIsElected() throws Exception {
        int port = JadeBridgeTest.freePort();
        try (Platform p = Boot.start(new String[]{"-name", "boothttp", "-ports", "7791-7799", "-profile", "closed",
                "-http", Integer.toString(port), "-agents", "echo:io.concord.core.testkit.EchoAgent"},
                new PrintStream(new ByteArrayOutputStream()))) {
            // The agent is alone, so container at once; its gateway starts as it takes the role.
            CompletableFuture<Void> container = new CompletableFuture<>();
            p.runtime().execute(() -> {
                ContainerLayer l = Platform.containerLayer(p.runtime(), AID.local("echo", "boothttp"));
                Consumer<ContainerLayer> check = x -> {
                    if (x.role() == ContainerLayer.Role.CONTAINER) {
                        container.complete(null);
                    }
                };
                l.addListener(check);
                check.accept(l);
            });
            container.get(20, TimeUnit.SECONDS);
            HttpClient c = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
            HttpRequest get = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/acc")).GET().build();
            assertEquals(405, c.send(get, HttpResponse.BodyHandlers.discarding()).statusCode(), "the ACC answers (it takes POST only)");
        }
    }
}
