package io.concord.bench.jade;

import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.wrapper.AgentController;
import jade.wrapper.ContainerController;
import jade.wrapper.StaleProxyException;

import java.io.IOException;
import java.net.ServerSocket;

/** A JADE 4.3 main container in this JVM, without GUI, MTP or main detection. */
public final class JadePlatform implements AutoCloseable {
    private final ContainerController main;
    private final int port;

    public JadePlatform() {
        this("bench", 0);
    }

    /**
     * A main container of its own platform; with {@code httpPort > 0} it serves JADE's HTTP MTP at
     * {@code http://127.0.0.1:httpPort/acc}, with the parser fix JADE 4.3 needs on Java 17.
     */
    public JadePlatform(String platformId, int httpPort) {
        port = freePort();
        Runtime rt = Runtime.instance();
        rt.setCloseVM(false);
        Profile p = new ProfileImpl();
        p.setParameter(Profile.GUI, "false");
        p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(Profile.LOCAL_PORT, Integer.toString(port));
        p.setParameter(Profile.PLATFORM_ID, platformId);
        if (httpPort > 0) {
            p.setParameter(Profile.MTPS, "jade.mtp.http.MessageTransportProtocol(http://127.0.0.1:" + httpPort + "/acc)");
            p.setParameter("jade_mtp_http_parser", "io.concord.jade.JadeSaxParser");
        } else {
            p.setParameter(Profile.NO_MTP, "true");
        }
        p.setParameter(Profile.DETECT_MAIN, "false");
        main = rt.createMainContainer(p);
        if (main == null) {
            throw new IllegalStateException("JADE could not start its main container on port " + port);
        }
    }

    public static int freePort() {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    public int port() {
        return port;
    }

    public AgentController start(String name, Class<?> cls, Object... args) throws StaleProxyException {
        AgentController a = main.createNewAgent(name, cls.getName(), args);
        a.start();
        return a;
    }

    @Override
    public void close() {
        try {
            main.kill();
        } catch (StaleProxyException | RuntimeException e) {
            // already gone
        }
    }
}
