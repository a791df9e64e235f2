package jade.core;

/** A transport address (kept for JADE's signatures). */
public interface TransportAddress extends jade.util.leap.Serializable {
    String getProto();

    String getHost();

    String getPort();

    String getFile();

    String getAnchor();
}
