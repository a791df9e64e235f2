package jade.core;

/** Where an agent can be: a container. */
public interface Location extends jade.util.leap.Serializable {
    String getID();

    String getName();

    String getProtocol();

    String getAddress();
}
