package jade.core;

/** A container's identifier: its name and address. */
public class ContainerID implements Location {
    private static final long serialVersionUID = 1L;
    private String name;
    private String address;

    public ContainerID() {
    }

    public ContainerID(String name, TransportAddress address) {
        this.name = name;
        this.address = address == null ? null : address.toString();
    }

    @Override
    public String getID() {
        return name + "@" + address;
    }

    @Override
    public String getName() {
        return name;
    }

    public void setName(String n) {
        name = n;
    }

    @Override
    public String getProtocol() {
        return "Concord";
    }

    @Override
    public String getAddress() {
        return address;
    }

    public void setAddress(String a) {
        address = a;
    }

    @Override
    public String toString() {
        return name;
    }
}
